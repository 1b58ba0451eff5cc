package org.tinysep.device.support.delivery;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * What the ordered hand-off costs per payload (issue 29, item 1): in a burst, the receive thread wakes the
 * dispatcher once per burst, not once per payload (a dispatcher that parked as soon as the queue was empty cost a
 * wake-up, a system call on the receive thread and a scheduling delay, for nearly every payload); order is kept.
 * At a slow pace the dispatcher does not spin in vain (on a 2-core gateway that core is the receive thread's).
 */
class HandOffCostTest {

    private static final int PAYLOADS = 20_000;
    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private final DriverContext context = new DriverContext(null, "driver-uid", "TestRadio",
            new RecordingLogs(() -> T0).reporter(), new PlatformClock(() -> T0));

    /** One listener recording what it got. */
    private static final class Recorder extends GuardedLane<Integer> {
        final List<Integer> got = new ArrayList<>(); // only the dispatcher adds

        @Override
        protected void call(Integer item) {
            got.add(item);
        }

        @Override
        protected String describe() {
            return "The recorder";
        }
    }

    @Test
    void atASlowPaceTheDispatcherParksAtOnce() throws InterruptedException {
        try (OrderedDelivery d = new OrderedDelivery(context, "The test radio")) {
            Recorder r = new Recorder();
            for (int i = 0; i < 200; i++) { // a payload every 2 ms, far apart from the next
                assertTrue(d.submit(new ToLanes<>(i, r)));
                Thread.sleep(2);
            }
            assertTrue(d.awaitDelivered(Duration.ofSeconds(10)));
            assertEquals(200, r.got.size());
            assertTrue(d.spinsInVain() <= 20, "spins in vain for 200 payloads 2 ms apart: " + d.spinsInVain());
        }
    }

    @Test
    void aBurstCostsFewWakeUpsAndKeepsItsOrder() {
        try (OrderedDelivery d = new OrderedDelivery(context, "The test radio")) {
            Recorder r = new Recorder();
            // a payload every ~3 µs, as a 2-core gateway receives them at its loss-free limit
            for (int i = 0; i < PAYLOADS; i++) {
                assertTrue(d.submit(new ToLanes<>(i, r)));
                long until = System.nanoTime() + 3_000;
                while (System.nanoTime() - until < 0) {
                    Thread.onSpinWait();
                }
            }
            assertTrue(d.awaitDelivered(Duration.ofSeconds(10)));
            for (int i = 0; i < PAYLOADS; i++) {
                assertEquals(i, r.got.get(i));
            }
            long wakeups = d.wakeups();
            assertTrue(wakeups < PAYLOADS / 100, "wake-ups of the dispatcher for " + PAYLOADS + " payloads: " + wakeups);
        }
    }
}
