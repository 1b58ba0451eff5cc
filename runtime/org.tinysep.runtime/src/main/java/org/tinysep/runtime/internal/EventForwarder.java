package org.tinysep.runtime.internal;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;

/**
 * Hands event-log entries to a slow sink (SLF4J output) on its own executor, so that recording never does I/O on
 * the caller's thread. It reads the ring itself, so nothing queues up beyond the ring: if the sink falls behind by
 * more than the ring's capacity, the overwritten entries are counted and reported once per gap.
 * The executor must run one task at a time (a single-thread executor).
 */
final class EventForwarder {

    private static final Logger LOG = LoggerFactory.getLogger(EventForwarder.class);
    private static final int BATCH = 256;

    private final RingBuffer<EventEntry> ring;
    private final Executor executor;
    private final Consumer<EventEntry> sink;
    private final AtomicBoolean scheduled = new AtomicBoolean();
    private final AtomicLong skipped = new AtomicLong();
    private long forwarded; // only touched by drain(), which runs one at a time

    EventForwarder(RingBuffer<EventEntry> ring, Executor executor, Consumer<EventEntry> sink) {
        this.ring = ring;
        this.executor = executor;
        this.sink = sink;
        this.forwarded = ring.lastSequence();
    }

    /** Called after each append, from any thread: schedules a drain unless one is pending. Never blocks. */
    void signal() {
        if (scheduled.compareAndSet(false, true)) {
            try {
                executor.execute(this::drain);
            } catch (RejectedExecutionException e) {
                scheduled.set(false); // shutting down: the entry stays in the ring
            }
        }
    }

    /** @return how many entries were overwritten before they could be forwarded */
    long skipped() {
        return skipped.get();
    }

    private void drain() {
        scheduled.set(false); // entries appended from now on schedule another drain
        List<EventEntry> batch;
        while (!(batch = ring.after(forwarded, BATCH)).isEmpty()) {
            long gap = batch.get(0).sequence() - forwarded - 1;
            if (gap > 0) {
                skipped.addAndGet(gap);
                LOG.warn("{} event-log entries were overwritten before they could be logged", gap);
            }
            for (EventEntry e : batch) {
                try {
                    sink.accept(e);
                } catch (RuntimeException ex) {
                    LOG.warn("Could not log event-log entry {}: {}", e.sequence(), ex.toString());
                }
                forwarded = e.sequence();
            }
        }
    }
}
