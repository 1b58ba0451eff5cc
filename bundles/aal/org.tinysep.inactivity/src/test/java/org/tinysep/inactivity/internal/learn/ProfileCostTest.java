package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.ZonedDateTime;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.AllocationMeter;

/**
 * Issue 29, item 1: the learned profile is asked for per activity; within the local day it was built for the answer
 * needs no date arithmetic (a zoned date per question was a tenth of Inactivity Recognition's time per movement
 * report), and the day still turns at the home's local midnight, also on the night the clocks change.
 */
class ProfileCostTest {

    private static final ZoneId HOME = ZoneId.of("Europe/Zurich");

    private static HistoryLearner learner() {
        HistoryLearner l = new HistoryLearner(HOME, new SleepRule(21, 7, HOME), LearningSettings.defaults());
        Instant start = ZonedDateTime.of(2026, 10, 15, 14, 0, 0, 0, HOME).toInstant();
        for (int d = 0; d < 10; d++) {
            l.add(new Sighting(start.plus(Duration.ofDays(d)), "Bathroom", "Bathroom", "Bathroom", false));
            l.add(new Sighting(start.plus(Duration.ofDays(d)).plusSeconds(1200), "Kitchen", "Kitchen", "Kitchen",
                    false));
        }
        l.loaded();
        return l;
    }

    @Test
    void askingWithinTheDayItWasBuiltForAllocatesNothing() {
        HistoryLearner l = learner();
        Instant morning = ZonedDateTime.of(2026, 10, 25, 9, 0, 0, 0, HOME).toInstant();
        QuietProfile p = l.profile(morning);
        Instant[] times = new Instant[40_000]; // made before: the questions' times are no cost of the answer
        for (int k = 0; k < times.length; k++) {
            times[k] = morning.plusMillis(100L * k);
        }
        int[] i = {0};
        double bytes = AllocationMeter.bytesPerCall(20_000, () -> l.profile(times[i[0]++]));
        assertTrue(bytes < 16, "bytes allocated per question within the day: " + bytes);
        assertSame(p, l.profile(morning.plusSeconds(3600)));
    }

    @Test
    void theDayTurnsAtLocalMidnightAlsoWhenTheClocksChange() {
        HistoryLearner l = learner();
        // 25 Oct 2026: the clocks go back in Zurich (a 25-hour day)
        Instant lastSecond = ZonedDateTime.of(2026, 10, 25, 23, 59, 59, 0, HOME).toInstant();
        QuietProfile late = l.profile(ZonedDateTime.of(2026, 10, 25, 1, 0, 0, 0, HOME).toInstant());
        assertSame(late, l.profile(lastSecond), "the same local day, 23 h later");
        assertNotSame(late, l.profile(lastSecond.plusSeconds(1)), "learned anew at local midnight");
    }

    @Test
    void mergingSightingsLessThanAMinuteApartKeepsItsMeaning() {
        Random r = new Random(29);
        Instant t = Instant.parse("2026-11-23T09:00:00Z");
        for (int k = 0; k < 100_000; k++) {
            Instant a = t.plusNanos(r.nextLong(1_000_000_000_000L));
            Instant b = a.plusNanos(r.nextInt(4) == 0 ? 60_000_000_000L + r.nextInt(3) - 1
                    : r.nextLong(120_000_000_000L));
            assertEquals(Duration.between(a, b).compareTo(HistoryLearner.MERGE) < 0,
                    HistoryLearner.withinMerge(a, b), a + " .. " + b);
        }
    }
}
