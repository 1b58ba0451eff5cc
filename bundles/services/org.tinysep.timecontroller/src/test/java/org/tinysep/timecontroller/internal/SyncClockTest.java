package org.tinysep.timecontroller.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.ClockMode;
import org.tinysep.timecontroller.internal.SyncClock.Outcome;

/** The clock's state machine against a hand-moved system clock. */
class SyncClockTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private final AtomicReference<Instant> system = new AtomicReference<>(T0);
    private final SyncClock clock = new SyncClock(system::get, ClockMode.REAL);

    private void systemAdvances(long seconds) {
        system.set(system.get().plusSeconds(seconds));
    }

    @Test
    void realModeFollowsTheSystemClockAndRefusesTicks() {
        assertEquals(ClockMode.REAL, clock.mode());
        systemAdvances(5);
        assertEquals(T0.plusSeconds(5), clock.now());
        SyncClock.TickResult r = clock.tick(1, T0.plusSeconds(100));
        assertEquals(Outcome.NOT_EXTERNAL, r.outcome());
        assertEquals(T0.plusSeconds(5), clock.now());
    }

    @Test
    void externalModeHoldsTheSwitchInstantUntilATick() {
        systemAdvances(3);
        assertEquals(Optional.of(T0.plusSeconds(3)), clock.switchTo(ClockMode.EXTERNAL));
        systemAdvances(60);
        assertEquals(T0.plusSeconds(3), clock.now(), "held, whatever the system clock does");
        assertEquals(Optional.empty(), clock.switchTo(ClockMode.EXTERNAL), "no change, no announcement");

        SyncClock.TickResult r = clock.tick(1, T0.plusSeconds(4));
        assertEquals(new SyncClock.TickResult(Outcome.ADVANCED, T0.plusSeconds(4)), r);
        assertEquals(T0.plusSeconds(4), clock.now());
        assertEquals(Outcome.ADVANCED, clock.tick(2, T0.plusSeconds(4)).outcome(), "equal is allowed");
        assertEquals(Outcome.ADVANCED, clock.tick(3, T0.plus(Duration.ofDays(1))).outcome(), "a jump of a day");
        assertEquals(T0.plus(Duration.ofDays(1)), clock.now());
    }

    @Test
    void aBackwardsTickIsRefusedAndChangesNothing() {
        clock.switchTo(ClockMode.EXTERNAL);
        clock.tick(1, T0.plusSeconds(10));
        SyncClock.TickResult r = clock.tick(2, T0.plusSeconds(9));
        assertEquals(Outcome.BACKWARDS, r.outcome());
        assertEquals(T0.plusSeconds(10), r.now());
        assertEquals(T0.plusSeconds(10), clock.now());
        assertEquals(Outcome.ADVANCED, clock.tick(3, T0.plusSeconds(11)).outcome(), "the link goes on");
    }

    @Test
    void aRetransmittedTickIsRecognisedByItsSequenceNumber() {
        clock.switchTo(ClockMode.EXTERNAL);
        assertEquals(Outcome.ADVANCED, clock.tick(7, T0.plusSeconds(1)).outcome());
        assertEquals(Outcome.REPEATED, clock.tick(7, T0.plusSeconds(1)).outcome());
        assertEquals(Outcome.ADVANCED, clock.tick(8, T0.plusSeconds(1)).outcome(), "new seq, same second: re-fires");
        assertEquals(Outcome.BACKWARDS, clock.tick(7, T0).outcome(), "same seq, other instant: a normal tick");
    }

    @Test
    void backToRealJumpsToTheSystemClockEvenBackwards() {
        clock.switchTo(ClockMode.EXTERNAL);
        clock.tick(1, T0.plus(Duration.ofDays(2)));
        systemAdvances(30);
        assertEquals(Optional.of(T0.plusSeconds(30)), clock.switchTo(ClockMode.REAL));
        assertEquals(T0.plusSeconds(30), clock.now());
        systemAdvances(1);
        clock.switchTo(ClockMode.EXTERNAL);
        assertEquals(T0.plusSeconds(31), clock.now(), "held at the system time again");
        assertEquals(Outcome.ADVANCED, clock.tick(1, T0.plusSeconds(32)).outcome(),
                "sequence numbers start afresh after a switch");
    }

    @Test
    void startsInTheConfiguredMode() {
        SyncClock external = new SyncClock(system::get, ClockMode.EXTERNAL);
        assertEquals(ClockMode.EXTERNAL, external.mode());
        systemAdvances(9);
        assertTrue(external.now().equals(T0));
    }
}
