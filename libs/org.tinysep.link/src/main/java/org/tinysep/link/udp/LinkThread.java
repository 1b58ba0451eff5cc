package org.tinysep.link.udp;

import java.time.Duration;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * The one named thread a link runs on, written once: the receive loop of a {@link DatagramLink}, the Sun
 * SPOT SDK link's open-and-receive task and its retries. {@link #close()} shuts it down and waits up to
 * {@link #CLOSE_WAIT} for the running task (a receive loop ends once its socket is closed), then interrupts it.
 */
public final class LinkThread implements AutoCloseable {

    /** How long {@link #close()} waits for the running task before it interrupts it. */
    public static final Duration CLOSE_WAIT = Duration.ofSeconds(2);

    private final ScheduledThreadPoolExecutor executor;

    /** @param name the thread's name, e.g. {@code BusRadioSunSpot-sdk}; no thread starts before the first task */
    public LinkThread(String name) {
        executor = new ScheduledThreadPoolExecutor(1, r -> new Thread(r, name));
        executor.setExecuteExistingDelayedTasksAfterShutdownPolicy(false);
    }

    /**
     * Runs a task on the thread now (after the tasks before it).
     *
     * @throws RejectedExecutionException if the thread was closed
     */
    public void execute(Runnable task) {
        executor.execute(task);
    }

    /** Runs a task on the thread after {@code delay}; nothing happens once the thread is closed or closing. */
    public void schedule(Runnable task, Duration delay) {
        try {
            executor.schedule(task, delay.toMillis(), TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            // closing: the link is going away
        }
    }

    /** Drops the tasks not started yet, waits up to {@link #CLOSE_WAIT} for the running one, then interrupts it. */
    @Override
    public void close() {
        executor.shutdown();
        try {
            if (!executor.awaitTermination(CLOSE_WAIT.toMillis(), TimeUnit.MILLISECONDS)) {
                executor.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
