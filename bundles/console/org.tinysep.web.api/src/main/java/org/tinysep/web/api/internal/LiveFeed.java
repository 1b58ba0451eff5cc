package org.tinysep.web.api.internal;

import java.util.List;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArraySet;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.function.ToLongFunction;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Feeds live Server-Sent Events streams from one log: every {@value #PERIOD_MS} ms it reads the log's newest
 * entries ({@code recent}) and hands those with a higher sequence number than seen before to every subscriber,
 * already formatted as SSE messages ({@code id: <sequence>}). One poller per log, whatever the number of
 * streams, and none while no stream is open (an idle gateway should not wake up five times a second
 * for nobody); a subscriber that falls {@value #QUEUE} messages behind is cut off (its browser reconnects with
 * {@code Last-Event-ID} and {@link #subscribe} gives it the gap).
 *
 * @param <E> EventEntry or PacketEntry
 */
public final class LiveFeed<E> implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(LiveFeed.class);
    static final long PERIOD_MS = 200;
    static final int QUEUE = 2000;
    private static final int WINDOW = 1000;
    /** Put into a subscriber's queue to end its stream. */
    static final String END = "\u0000end";

    /** One open stream. */
    public static final class Subscriber {
        final BlockingQueue<String> queue = new ArrayBlockingQueue<>(QUEUE);
        volatile boolean cut;
    }

    private final Function<Integer, List<E>> recent;
    private final ToLongFunction<E> sequence;
    private final Function<E, String> format;
    private final String name;
    private final Set<Subscriber> subscribers = new CopyOnWriteArraySet<>();
    private final ScheduledExecutorService executor;
    private volatile long last;
    private ScheduledFuture<?> polling; // guarded by subscribers

    public LiveFeed(String name, Function<Integer, List<E>> recent, ToLongFunction<E> sequence,
            Function<E, String> format) {
        this.name = name;
        this.recent = recent;
        this.sequence = sequence;
        this.format = format;
        this.executor = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "tinysep-web-live-" + name);
            t.setDaemon(true);
            return t;
        });
    }

    /** @return a new subscriber; entries after {@code after} (a sequence number, or -1 for only new ones) come first */
    public Subscriber subscribe(long after) {
        Subscriber s = new Subscriber();
        synchronized (subscribers) {
            if (polling == null) { // the first stream: the log's entries now are the past, the poller sends the rest
                List<E> now = recent.apply(1);
                last = now.isEmpty() ? -1 : sequence.applyAsLong(now.get(now.size() - 1));
                polling = executor.scheduleWithFixedDelay(this::poll, PERIOD_MS, PERIOD_MS, TimeUnit.MILLISECONDS);
            }
            if (after >= 0) {
                long upTo = last; // newer entries come from the poller, so none comes twice
                recent.apply(WINDOW).stream().filter(e -> sequence.applyAsLong(e) > after)
                        .filter(e -> sequence.applyAsLong(e) <= upTo).map(format).forEach(s.queue::offer);
            }
            subscribers.add(s);
        }
        return s;
    }

    public void unsubscribe(Subscriber s) {
        synchronized (subscribers) {
            subscribers.remove(s);
            if (subscribers.isEmpty() && polling != null) {
                polling.cancel(false);
                polling = null;
            }
        }
    }

    /** @return whether the poller runs (only while a stream is open) */
    boolean polling() {
        synchronized (subscribers) {
            return polling != null;
        }
    }

    /** @return how many streams are open */
    public int size() {
        return subscribers.size();
    }

    private void poll() {
        synchronized (subscribers) { // a stream subscribing meanwhile gets each entry once: backlog or poll
            pollLocked();
        }
    }

    private void pollLocked() {
        try {
            List<E> fresh = recent.apply(WINDOW).stream().filter(e -> sequence.applyAsLong(e) > last).toList();
            if (fresh.isEmpty()) {
                return;
            }
            last = sequence.applyAsLong(fresh.get(fresh.size() - 1));
            List<String> messages = fresh.stream().map(format).toList();
            for (Subscriber s : subscribers) {
                for (String m : messages) {
                    if (!s.queue.offer(m)) {
                        s.cut = true;
                        s.queue.clear();
                        s.queue.offer(END);
                        unsubscribe(s);
                        LOG.info("A live {} stream fell {} entries behind and was closed; the browser reconnects",
                                name, QUEUE);
                        break;
                    }
                }
            }
        } catch (RuntimeException e) {
            LOG.warn("Live {} feed: {}", name, e.toString());
        }
    }

    /** Ends every stream and stops polling. */
    @Override
    public void close() {
        executor.shutdownNow();
        for (Subscriber s : subscribers) {
            s.queue.clear();
            s.queue.offer(END);
        }
        subscribers.clear();
    }
}
