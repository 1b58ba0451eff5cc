package org.tinysep.link.udp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/** The one thread of a link: its name, its tasks in order, and a close that waits for the running task. */
class LinkThreadTest {

    @Test
    void tasksRunInOrderOnTheNamedThread() throws Exception {
        LinkThread thread = new LinkThread("test-link");
        AtomicReference<String> name = new AtomicReference<>();
        StringBuilder order = new StringBuilder();
        CountDownLatch done = new CountDownLatch(1);
        thread.execute(() -> order.append('a'));
        thread.schedule(() -> order.append('b'), Duration.ZERO);
        thread.execute(() -> {
            name.set(Thread.currentThread().getName());
            done.countDown();
        });
        assertTrue(done.await(10, TimeUnit.SECONDS));
        thread.close();
        assertEquals("test-link", name.get());
        assertEquals("ab", order.toString());
    }

    @Test
    void closeWaitsForTheRunningTaskAndDropsTheLaterOnes() throws Exception {
        LinkThread thread = new LinkThread("test-link");
        CountDownLatch running = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        AtomicBoolean finished = new AtomicBoolean();
        AtomicBoolean later = new AtomicBoolean();
        thread.execute(() -> {
            running.countDown();
            try {
                release.await(); // like a receive loop that ends when its socket closes
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            finished.set(true);
        });
        thread.schedule(() -> later.set(true), Duration.ofHours(1));
        assertTrue(running.await(10, TimeUnit.SECONDS));
        release.countDown();
        thread.close();
        assertTrue(finished.get(), "close returned only after the running task ended");
        assertTrue(!later.get(), "a task not started yet is dropped");

        thread.schedule(() -> later.set(true), Duration.ZERO); // closed: nothing, no exception
        assertThrows(RejectedExecutionException.class, () -> thread.execute(() -> later.set(true)));
        assertTrue(!later.get());
    }

    @Test
    void closeInterruptsATaskThatDoesNotEndInTime() throws Exception {
        LinkThread thread = new LinkThread("test-link");
        CountDownLatch running = new CountDownLatch(1);
        AtomicBoolean interrupted = new AtomicBoolean();
        thread.execute(() -> {
            running.countDown();
            try {
                new CountDownLatch(1).await(); // never released
            } catch (InterruptedException e) {
                interrupted.set(true);
            }
        });
        assertTrue(running.await(10, TimeUnit.SECONDS));
        thread.close(); // waits CLOSE_WAIT, then interrupts
        assertTrue(interrupted.get() || awaitInterrupt(interrupted), "the stuck task was interrupted");
    }

    private static boolean awaitInterrupt(AtomicBoolean interrupted) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!interrupted.get() && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        return interrupted.get();
    }
}
