package org.tinysep.device.support.delivery;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * The slow-call watchdog looks only while a payload is in hand (issue 29: an idle platform's radios woke a thread
 * four times a second each for it), and a slow call after a pause is still taken out of the ordered path.
 */
class WatchdogTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private static final Duration SLOW = Duration.ofMillis(100); // a round every 25 ms while armed
    private final DriverContext context = new DriverContext(null, "driver-uid", "TestRadio",
            new RecordingLogs(() -> T0).reporter(), new PlatformClock(() -> T0));

    /** A listener that records what it got and, for the payload {@code blockOn}, waits for {@code release}. */
    private static final class Lane extends GuardedLane<Integer> {
        final List<Integer> got = new CopyOnWriteArrayList<>();
        final CountDownLatch release = new CountDownLatch(1);
        final int blockOn;

        Lane(int blockOn) {
            this.blockOn = blockOn;
        }

        @Override
        protected void call(Integer item) {
            if (item == blockOn) {
                try {
                    release.await(10, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            got.add(item);
        }

        @Override
        protected String describe() {
            return "The test lane";
        }
    }

    @Test
    void anIdleDeliveryRunsNoWatchdogRounds() throws InterruptedException {
        try (OrderedDelivery d = new OrderedDelivery(context, "The test radio", SLOW, 64, 16)) {
            Lane lane = new Lane(-1);
            assertTrue(d.submit(new ToLanes<>(1, lane)));
            assertTrue(d.awaitDelivered(Duration.ofSeconds(5)));
            Thread.sleep(150); // the round after the delivery stops the rounds
            long before = d.watchRounds();
            Thread.sleep(500); // 20 rounds at a quarter of the limit
            assertEquals(before, d.watchRounds(), "watchdog rounds in 500 ms of an idle delivery");
            assertTrue(d.submit(new ToLanes<>(2, lane)));
            assertTrue(d.awaitDelivered(Duration.ofSeconds(5)));
            assertEquals(List.of(1, 2), lane.got);
        }
    }

    @Test
    void aSlowCallAfterAPauseIsStillTakenOutOfTheOrderedPath() throws InterruptedException {
        try (OrderedDelivery d = new OrderedDelivery(context, "The test radio", SLOW, 64, 16)) {
            Lane slow = new Lane(2);
            Lane healthy = new Lane(-1);
            assertTrue(d.submit(new ToLanes<>(1, slow, healthy)));
            assertTrue(d.awaitDelivered(Duration.ofSeconds(5)));
            Thread.sleep(300); // idle: the rounds stopped
            assertTrue(d.submit(new ToLanes<>(2, slow, healthy))); // the slow lane blocks on 2
            assertTrue(d.submit(new ToLanes<>(3, healthy)));
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (healthy.got.size() < 3 && System.nanoTime() < end) {
                Thread.sleep(10);
            }
            assertEquals(1, d.quarantines(), "the call blocked since the pause was taken out of the ordered path");
            assertEquals(List.of(1, 2, 3), healthy.got, "the healthy lane got its payloads while the slow one waits");
            slow.release.countDown();
        }
    }
}
