package org.tinysep.drivers.internal;

import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Runs a save shortly after a request, once for any number of requests in between (a burst of bundle events during
 * a start-up or an update becomes one write). One thread; {@link #close()} ends it.
 */
final class CoalescingSaver implements AutoCloseable {

    private final ScheduledExecutorService executor = Executors.newSingleThreadScheduledExecutor(
            r -> new Thread(r, "tinysep-drivers-save"));
    private final AtomicBoolean pending = new AtomicBoolean();
    private final Runnable save;
    private final long delayMillis;

    CoalescingSaver(Runnable save, long delayMillis) {
        this.save = save;
        this.delayMillis = delayMillis;
    }

    /** Asks for a save within {@code delayMillis}; does nothing when one is already pending. */
    void request() {
        if (pending.compareAndSet(false, true)) {
            try {
                executor.schedule(() -> {
                    pending.set(false);
                    save.run();
                }, delayMillis, TimeUnit.MILLISECONDS);
            } catch (RejectedExecutionException e) {
                pending.set(false); // closed
            }
        }
    }

    @Override
    public void close() {
        executor.shutdownNow();
    }
}
