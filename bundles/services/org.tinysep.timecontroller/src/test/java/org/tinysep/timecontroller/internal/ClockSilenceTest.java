package org.tinysep.timecontroller.internal;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.ClockMode;

/** When EXTERNAL time counts as abandoned by its synchroniser (syncTimeout), against a hand-moved monotonic clock. */
class ClockSilenceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private static final long S = 1_000_000_000L;
    private final AtomicLong nanos = new AtomicLong(5 * S);

    @Test
    void externalTimeWithoutTicksForTheTimeoutIsSilent() {
        ClockService clock = new ClockService("uid", new SyncClock(() -> T0, ClockMode.EXTERNAL), nanos::get);
        nanos.addAndGet(119 * S);
        assertFalse(clock.silentFor(120), "119 s after the start");
        nanos.addAndGet(S);
        assertTrue(clock.silentFor(120), "120 s without a TICK");
        assertFalse(clock.silentFor(0), "0: never");
        clock.tick(1, T0.plusSeconds(1));
        assertFalse(clock.silentFor(120), "a TICK restarts the count");
        nanos.addAndGet(200 * S);
        assertTrue(clock.silentFor(120));
        clock.switchTo(ClockMode.REAL, t -> { });
        assertFalse(clock.silentFor(120), "REAL time is never silent");
        nanos.addAndGet(500 * S);
        clock.switchTo(ClockMode.EXTERNAL, t -> { });
        assertFalse(clock.silentFor(120), "a switch to EXTERNAL restarts the count");
    }
}
