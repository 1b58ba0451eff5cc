package org.tinysep.flatoccupancy.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Duration;
import java.time.Instant;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.Occupancy;

/** The occupancy algorithm in virtual time: each step at an explicit instant. */
class OccupancyLogicTest {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");
    private final OccupancyLogic logic = new OccupancyLogic(Duration.ofMinutes(10), Duration.ofSeconds(10), T0);

    private static Instant at(int seconds) {
        return T0.plusSeconds(seconds);
    }

    @Test
    void unknownUntilTheFirstEvidence() {
        assertEquals(Occupancy.UNKNOWN, logic.state());
        assertEquals(Optional.empty(), logic.tick(at(3600)));
        assertEquals(Occupancy.UNKNOWN, logic.state());
    }

    @Test
    void indoorMotionMeansOccupied() {
        assertEquals(Optional.of(Occupancy.OCCUPIED), logic.motion(at(5)));
        assertEquals(Optional.empty(), logic.motion(at(7)), "no repeated announcement");
        assertEquals(at(5), logic.since());
    }

    @Test
    void leavingEmptiesTheFlatExactlyWhenTheTimeoutEnds() {
        logic.motion(at(0));
        logic.outerDoorOpened(at(100));
        logic.outerDoorClosed(at(105));
        logic.motion(at(110)); // hall sensor still sees the leaving person within the 10 s grace
        assertEquals(Optional.empty(), logic.tick(at(105 + 599)));
        assertEquals(Occupancy.OCCUPIED, logic.state());
        assertEquals(Optional.of(Occupancy.UNOCCUPIED), logic.tick(at(105 + 600)));
        assertEquals(at(705), logic.since(), "stamped with the deadline, not the late tick");
    }

    @Test
    void motionAfterTheGraceCancelsTheLeaveCheck() {
        logic.motion(at(0));
        logic.outerDoorClosed(at(100));
        logic.motion(at(200));
        assertEquals(Optional.empty(), logic.tick(at(100 + 600)));
        assertEquals(Occupancy.OCCUPIED, logic.state());
        assertEquals(Optional.empty(), logic.leaveDeadline());
    }

    @Test
    void arrivalThroughTheOuterDoorMeansOccupied() {
        logic.motion(at(0));
        logic.outerDoorClosed(at(10));
        logic.tick(at(700));
        assertEquals(Occupancy.UNOCCUPIED, logic.state());
        assertEquals(Optional.of(Occupancy.OCCUPIED), logic.outerDoorOpened(at(3600)));
    }

    @Test
    void doorOpenedAndClosedWithoutAnyoneEnteringEmptiesTheFlatAgain() {
        logic.outerDoorOpened(at(0));
        logic.outerDoorClosed(at(20));
        assertEquals(Occupancy.OCCUPIED, logic.state());
        assertEquals(Optional.of(Occupancy.UNOCCUPIED), logic.tick(at(620)));
    }

    /**
     * The clock check and the exit grace are answered from times kept when {@code since} or the last close change
     * (no sums per report): over random times, what they decide is what the sums decided.
     */
    @Test
    void keptTimesDecideAsTheSumsPerReportDid() {
        Random random = new Random(29);
        for (int i = 0; i < 100_000; i++) {
            Instant since = T0.plusMillis(random.nextInt(20_000));
            Instant close = random.nextBoolean() ? null : T0.plusMillis(random.nextInt(20_000));
            Instant now = T0.plusMillis(random.nextInt(20_000));
            OccupancyLogic l = new OccupancyLogic(Duration.ofMinutes(10), Duration.ofSeconds(10), T0);
            l.restore(new OccupancyLogic.Saved(Occupancy.OCCUPIED, since, close,
                    close == null ? null : close.plus(Duration.ofMinutes(10))));
            boolean wentBack = since.isAfter(now.plus(OccupancyLogic.CLOCK_SLACK))
                    || close != null && close.isAfter(now.plus(OccupancyLogic.CLOCK_SLACK));
            assertEquals(wentBack, l.rebase(now).isPresent(), since + " " + close + " " + now);
            if (!wentBack && close != null) {
                Instant at = T0.plusMillis(random.nextInt(40_000));
                boolean ignored = at.isBefore(close.plus(Duration.ofSeconds(10)));
                l.indoorActivity(at);
                assertEquals(ignored, l.leaveDeadline().isPresent(),
                        "activity at " + at + " after a close at " + close + " within the exit grace");
            }
        }
    }

    @Test
    void timeoutMustExceedGrace() {
        assertThrows(IllegalArgumentException.class,
                () -> new OccupancyLogic(Duration.ofSeconds(5), Duration.ofSeconds(5), T0));
    }
}
