package org.tinysep.runtime.internal.log;

import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.IntSupplier;

/**
 * Runs a {@link RingDrain} on the writer thread's own beat while entries keep coming, so that the recording thread
 * (a bus radio's receive thread) hands the writer nothing per entry: no task, no wake-up. While the beat runs,
 * {@link #signal} is two field reads. The writer drains every {@code periodMillis}; after {@code idleRounds} rounds
 * that found nothing, the beat stops and the next entry starts it again (one task per pause, not per entry). A burst
 * that fills {@code urgentBacklog} ring slots before the next beat wakes the writer at once, so the ring is not
 * overwritten while the writer sleeps.
 */
final class Cadence {

    private final RingDrain<?> drain;
    private final ScheduledExecutorService thread;
    private final long periodMillis;
    private final int idleRounds;
    private final IntSupplier urgentBacklog;
    private final AtomicBoolean running = new AtomicBoolean();
    private final AtomicBoolean urgent = new AtomicBoolean();
    private int idle; // writer thread only

    /**
     * @param thread        the writer thread: a single-thread scheduled executor
     * @param urgentBacklog unwritten entries that wake the writer before its beat (a quarter of the ring: read on
     *                      each entry, so it must be cheap and lock-free)
     */
    Cadence(RingDrain<?> drain, ScheduledExecutorService thread, long periodMillis, int idleRounds,
            IntSupplier urgentBacklog) {
        this.drain = drain;
        this.thread = thread;
        this.periodMillis = periodMillis;
        this.idleRounds = idleRounds;
        this.urgentBacklog = urgentBacklog;
    }

    /** After each append, on the recording thread, with the entry's sequence number. Never blocks. */
    void signal(long sequence) {
        if (!running.get()) {
            if (running.compareAndSet(false, true)) {
                next(periodMillis);
            }
        } else if (sequence - drain.drained() >= Math.max(1, urgentBacklog.getAsInt())
                && urgent.compareAndSet(false, true)) {
            try {
                thread.execute(() -> {
                    urgent.set(false);
                    drain.drain();
                });
            } catch (RejectedExecutionException e) {
                urgent.set(false); // shutting down: close() drains
            }
        }
    }

    /** @return whether the beat is running (entries came lately) */
    boolean running() {
        return running.get();
    }

    /** One beat, on the writer thread: drain, then beat again, or stop after enough empty rounds. */
    private void round() {
        long before = drain.drained();
        drain.drain();
        idle = drain.drained() == before ? idle + 1 : 0;
        if (idle < idleRounds) {
            next(periodMillis);
            return;
        }
        idle = 0;
        running.set(false);
        // an entry appended after the drain saw the beat still running and started nothing: start it for it
        if (drain.pending() && running.compareAndSet(false, true)) {
            next(periodMillis);
        }
    }

    private void next(long delayMillis) {
        try {
            thread.schedule(this::round, delayMillis, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            running.set(false); // shutting down: close() drains
        }
    }
}
