package org.tinysep.push.internal;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.service.MailDelivery;

/**
 * Publishes on the push channel's own threads, so that a slow or hanging push server never holds the caller (the
 * alert service's thread, which goes on to the next contact at once): {@link #submit} answers QUEUED with an id,
 * and {@link #delivery} gives the outcome once the server answered or the timeout passed, as the SMS channel does
 * for gammu-smsd. A few threads, so one hanging topic does not hold the next contact's push either. The last
 * {@value #KEPT} outcomes are kept.
 */
final class PushSender implements AutoCloseable {

    static final int KEPT = 500;
    private final ThreadPoolExecutor threads;
    private final String prefix = "push-" + Long.toString(System.currentTimeMillis(), 36) + "-";
    private final AtomicLong next = new AtomicLong();
    private final Consumer<ChannelDelivery> done;
    private final Map<String, ChannelDelivery> outcomes = new LinkedHashMap<>() {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, ChannelDelivery> eldest) {
            return size() > KEPT;
        }
    };

    /** @param done told (on a push thread) of every outcome, e.g. to update the channel's status */
    PushSender(int threadCount, Consumer<ChannelDelivery> done) {
        AtomicLong named = new AtomicLong();
        this.threads = new ThreadPoolExecutor(threadCount, threadCount, 30, TimeUnit.SECONDS,
                new LinkedBlockingQueue<>(), r -> new Thread(r, "tinysep-push-" + named.incrementAndGet()));
        threads.allowCoreThreadTimeOut(true);
        this.done = done;
    }

    /**
     * @param waiting what the message waits for, in words (QUEUED's detail until the outcome is known)
     * @return QUEUED with the id to ask {@link #delivery} about; FAILED when the channel is stopping
     */
    ChannelDelivery submit(String waiting, Supplier<ChannelDelivery> publish) {
        String id = prefix + next.incrementAndGet();
        keep(new ChannelDelivery(id, MailDelivery.Outcome.QUEUED, waiting));
        try {
            threads.execute(() -> {
                ChannelDelivery d;
                try {
                    d = publish.get();
                } catch (RuntimeException | LinkageError e) { // never left QUEUED for ever: say what went wrong
                    d = ChannelDelivery.failed("the push channel failed while publishing: " + e);
                }
                ChannelDelivery kept = new ChannelDelivery(id, d.outcome(), d.detail());
                done.accept(kept); // the status first: whoever reads the outcome finds the status updated
                keep(kept);
            });
        } catch (RejectedExecutionException e) {
            ChannelDelivery failed = new ChannelDelivery(id, MailDelivery.Outcome.FAILED, "the push channel is "
                    + "stopping; nothing was published");
            keep(failed);
            return failed;
        }
        return new ChannelDelivery(id, MailDelivery.Outcome.QUEUED, waiting);
    }

    /** @return the latest word on message {@code id}; UNKNOWN for an id of this channel no longer kept */
    Optional<ChannelDelivery> delivery(String id) {
        synchronized (outcomes) {
            ChannelDelivery d = outcomes.get(id);
            if (d != null) {
                return Optional.of(d);
            }
        }
        return id.startsWith("push-") ? Optional.of(new ChannelDelivery(id, MailDelivery.Outcome.UNKNOWN, "no "
                + "longer known to the push channel (it was restarted, or " + KEPT + " messages went since)"))
                : Optional.empty();
    }

    private void keep(ChannelDelivery d) {
        synchronized (outcomes) {
            outcomes.put(d.id(), d);
        }
    }

    /** Stops the threads: a publish under way is interrupted, queued ones are dropped. */
    @Override
    public void close() {
        threads.shutdownNow();
        try {
            threads.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
