package org.tinysep.runtime.internal.log;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.ToLongFunction;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Hands the entries appended to a ring to a slow sink (SLF4J output, a file) in batches on its own executor, so
 * that recording never does I/O on the caller's thread. It reads the ring itself, so nothing queues up beyond the
 * ring: if the sink falls behind by more than the ring's capacity, the overwritten entries are counted and
 * reported once per gap. The executor must run one task at a time (a single-thread executor).
 *
 * @param <E> the entry type
 */
final class RingDrain<E> {

    private static final Logger LOG = LoggerFactory.getLogger(RingDrain.class);
    static final int BATCH = 512;

    private final RingBuffer<E> ring;
    private final ToLongFunction<E> sequence;
    private final Executor executor;
    private final Consumer<List<E>> sink;
    private final String what;
    private final AtomicBoolean scheduled = new AtomicBoolean();
    private final AtomicLong skipped = new AtomicLong();
    private volatile long drained; // written only by drain(), which runs one at a time

    /**
     * @param what how the sink's work is described in the gap warning, e.g. {@code "logged"}
     */
    RingDrain(RingBuffer<E> ring, ToLongFunction<E> sequence, Executor executor, Consumer<List<E>> sink,
            String what) {
        this.ring = ring;
        this.sequence = sequence;
        this.executor = executor;
        this.sink = sink;
        this.what = what;
        this.drained = ring.lastSequence();
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

    /** @return how many entries were overwritten before they could be handed to the sink */
    long skipped() {
        return skipped.get();
    }

    /** @return the sequence number of the last entry handed to the sink */
    long drained() {
        return drained;
    }

    /** @return whether the ring holds entries not yet handed to the sink */
    boolean pending() {
        return ring.lastSequence() > drained;
    }

    /** Hands every entry not yet drained to the sink; runs on the executor (or, when stopping, on its caller). */
    void drain() {
        scheduled.set(false); // entries appended from now on schedule another drain
        List<E> batch;
        while (!(batch = ring.after(drained, BATCH)).isEmpty()) {
            long gap = sequence.applyAsLong(batch.get(0)) - drained - 1;
            if (gap > 0) {
                skipped.addAndGet(gap);
                LOG.warn("{} log entries were overwritten before they could be {}", gap, what);
            }
            try {
                sink.accept(batch);
            } catch (RuntimeException ex) {
                LOG.warn("Could not hand {} log entries to be {}: {}", batch.size(), what, ex.toString());
            }
            drained = sequence.applyAsLong(batch.get(batch.size() - 1));
        }
    }
}
