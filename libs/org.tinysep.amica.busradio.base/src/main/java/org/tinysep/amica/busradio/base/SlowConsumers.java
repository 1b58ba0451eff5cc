package org.tinysep.amica.busradio.base;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.DriverContext;

/**
 * A slow consumer never stalls the radio (issue 29 item 1): each listener of a bus device gets its payloads through
 * its own bounded queue, drained in order by a thread of this pool, so the receive thread only enqueues. A listener
 * that blocks (e.g. for seconds) holds only its own queue: the radio goes on decoding, the other listeners go on
 * being served. When its queue is full the newest payloads for it are dropped, counted, and said in plain words as
 * a PROBLEM at most once a minute. Under load a queue's thread drains many payloads per wake-up; a thread exists only
 * while its listener has work. {@link #awaitIdle} lets a lock-step tick wait until the payloads it handed over are
 * delivered (a listener known to be slow is not waited for). Closed with its driver.
 */
public final class SlowConsumers implements AutoCloseable {

    /** Payloads waiting per listener before the newest are dropped. */
    public static final int CAPACITY = 4_096;
    private static final long REPORT_NANOS = 60_000_000_000L;
    private static final Logger LOG = LoggerFactory.getLogger(SlowConsumers.class);

    private record Item(BusRadioAmicaProvider source, byte[] payload, Instant at) {
    }

    private final DriverContext context;
    private final ExecutorService pool;
    private final int capacity;
    private final Set<Lane> lanes = ConcurrentHashMap.newKeySet();
    private final AtomicLong dropped = new AtomicLong();

    public SlowConsumers(DriverContext context) {
        this(context, CAPACITY);
    }

    SlowConsumers(DriverContext context, int capacity) {
        this.context = context;
        this.capacity = capacity;
        AtomicInteger n = new AtomicInteger();
        this.pool = new ThreadPoolExecutor(0, Integer.MAX_VALUE, 30, TimeUnit.SECONDS, new SynchronousQueue<>(), r -> {
            Thread t = new Thread(r, context.driverName() + " delivery " + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    /** @return {@code listener} behind its own queue; {@code owner} names the node in reports, e.g. "AmICA node 1.17" */
    public BusRadioAmicaListener guard(BusRadioAmicaListener listener, String owner) {
        Lane lane = new Lane(listener, owner);
        lanes.add(lane);
        return lane;
    }

    /**
     * Stops a guarded listener whose connection closes: it gets nothing more from its queue.
     *
     * @return what was still queued for it, oldest first (its bus device holds it for a replacement listener)
     */
    List<Handover.Held> stop(BusRadioAmicaListener guarded) {
        lanes.remove(guarded);
        if (!(guarded instanceof SlowConsumers.Lane lane)) {
            return List.of();
        }
        lane.closed = true;
        List<Handover.Held> left = new ArrayList<>();
        for (Item i = lane.queue.poll(); i != null; i = lane.queue.poll()) {
            left.add(new Handover.Held(i.payload(), i.at()));
        }
        return left;
    }

    /** @return the listener behind a guarded one (e.g. the device, to name it), else {@code listener} itself */
    static Object unwrap(Object listener) {
        return listener instanceof SlowConsumers.Lane lane ? lane.listener : listener;
    }

    /** @return payloads dropped in total because a listener's queue was full */
    public long dropped() {
        return dropped.get();
    }

    /**
     * Waits until every listener not known to be slow has taken what was queued for it, at most {@code max}.
     *
     * @return whether all of them had
     */
    public boolean awaitIdle(Duration max) {
        long end = System.nanoTime() + max.toNanos();
        for (Lane l : lanes) {
            while (!l.idle() && !l.slow()) {
                if (System.nanoTime() - end >= 0) {
                    return false;
                }
                Thread.onSpinWait();
                Thread.yield();
            }
        }
        return true;
    }

    @Override
    public void close() {
        pool.shutdownNow();
        lanes.clear();
    }

    /** One listener's queue; it delivers in order on one pool thread at a time. */
    private final class Lane implements BusRadioAmicaListener, Runnable {
        private final BusRadioAmicaListener listener;
        private final String owner;
        private final ArrayBlockingQueue<Item> queue = new ArrayBlockingQueue<>(capacity);
        private final AtomicBoolean scheduled = new AtomicBoolean();
        private final AtomicLong droppedHere = new AtomicLong();
        private volatile long busySince; // 0 while not delivering
        private volatile boolean closed;
        private long unreported; // guarded by this
        private long lastReport = System.nanoTime() - REPORT_NANOS;
        private Instant since;

        Lane(BusRadioAmicaListener listener, String owner) {
            this.listener = listener;
            this.owner = owner;
        }

        @Override
        public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
            if (!queue.offer(new Item(source, payload, at))) {
                droppedHere.incrementAndGet();
                dropped.incrementAndGet();
                drop(at);
            }
            if (scheduled.compareAndSet(false, true)) {
                try {
                    pool.execute(this);
                } catch (RuntimeException e) { // closed: the driver stops
                    scheduled.set(false);
                }
            }
        }

        @Override
        public void run() {
            do {
                while (true) {
                    busySince = System.nanoTime(); // before the poll: a payload taken is never "idle"
                    Item i = closed ? null : queue.poll();
                    if (i == null) {
                        busySince = 0;
                        break;
                    }
                    try {
                        listener.payloadReceived(i.source(), i.payload(), i.at());
                    } catch (RuntimeException | LinkageError e) {
                        LOG.warn("Listener {} of {} failed: {}", listener.getClass().getName(), owner, e.toString());
                    }
                }
                scheduled.set(false);
            } while (!queue.isEmpty() && scheduled.compareAndSet(false, true));
        }

        boolean idle() {
            return queue.isEmpty() && busySince == 0;
        }

        /** @return whether it dropped payloads or has been on one payload for over a second */
        boolean slow() {
            long b = busySince;
            return droppedHere.get() > 0 || (b != 0 && System.nanoTime() - b > 1_000_000_000L);
        }

        private synchronized void drop(Instant at) {
            if (unreported++ == 0) {
                since = at;
            }
            long now = System.nanoTime();
            if (now - lastReport >= REPORT_NANOS) {
                String words = "The listener " + name() + " of " + owner + " is too slow: " + unreported
                        + " payload" + (unreported == 1 ? "" : "s") + " dropped since " + since + " (its queue of "
                        + capacity + " was full). The radio goes on receiving and the other listeners are served; "
                        + "what the slow one missed is lost";
                LOG.warn("{}", words);
                context.event(EventKind.PROBLEM, words);
                lastReport = now;
                unreported = 0;
            }
        }

        private String name() {
            if (listener instanceof Device d) {
                return "'" + d.name() + "'";
            }
            String n = listener.getClass().getSimpleName();
            int lambda = n.indexOf("$$Lambda");
            return n.isEmpty() || lambda == 0 ? listener.getClass().getName() : lambda > 0 ? n.substring(0, lambda) : n;
        }
    }
}
