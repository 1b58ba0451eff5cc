package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/**
 * Issue 28, item 1, checked on the home's own past: each past day is judged with limits learned from the days
 * before it; where the learned limits would have called for help more often than the fixed ones, the margin grows.
 */
class MarginCheckTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);

    /**
     * 14 days in the kitchen at 10:00: 10 min on the first 7 days, 40 min from day 7 on (a new habit). Judged day by
     * day with what the days before taught, days 7, 8 and 9 outlast the limit of x 1.5 (the first 40 min periods are
     * outliers against seven 10 min days); the fixed 90 min limit is never reached.
     */
    private static HistoryLearner newHabit() {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults()
                .withMinPeriodsToShorten(0));
        for (int d = 0; d < 14; d++) {
            l.add(new Sighting(History.at(d, "10:00"), "Kitchen", "Kitchen", "Kitchen", false));
            l.add(new Sighting(History.at(d, d < 7 ? "10:10" : "10:40"), "Hall", "Hall", "Hall", false));
        }
        return l;
    }

    @Test
    void quietPeriodsThatOutlastedWhatTheDaysBeforeTaughtLengthenTheMargin() {
        Limit l = new LearnedLimits(newHabit()).limitAfter(new Sighting(History.at(14, "10:00"), "Kitchen",
                "Kitchen", "Kitchen", false), Duration.ofMinutes(90), History.at(14, "10:00"));
        // usual 40 min (the 14 days' maxima); x 1.5 would give 1 h 10 min, but day by day it would have called for
        // help 3 times where the fixed limits never did; x 3 (twice the configured margin) would not have
        assertEquals(Duration.ofMinutes(130), l.limit(), l.explanation());
        assertTrue(l.explanation().contains("usual x 3 + 10 min"), l.explanation());
        assertTrue(l.explanation().contains("x 3 rather than x 1.5 because over the last 14 days, each day judged "
                + "with what the days before it taught, x 1.5 would have called for help 3 times where the fixed "
                + "limits called 0 times"), l.explanation());
    }

    @Test
    void theMarginStaysWhereTheFixedLimitsWouldHaveCalledAsOften() {
        // the same history with a fixed limit of 30 min: the fixed limits would have called 7 times, x 1.5 3 times
        Limit l = new LearnedLimits(newHabit()).limitAfter(new Sighting(History.at(14, "10:00"), "Kitchen",
                "Kitchen", "Kitchen", false), Duration.ofMinutes(30), History.at(14, "10:00"));
        assertEquals(Duration.ofMinutes(70), l.limit(), l.explanation());
        assertFalse(l.explanation().contains("rather than"), l.explanation());
    }

    @Test
    void eachDayIsJudgedOnlyWithTheDaysBeforeIt() {
        // left out one at a time but learned from all the others, no day would outlast its limit (the later 40 min
        // days teach 40 min to the earlier ones): the check is forward, as the detector met the days
        MarginCheck.Result r = MarginCheck.choose(QuietGaps.of(newHabit().memory().sightings(), java.util.List.of(),
                SLEEP), ZoneOffset.UTC, LearningSettings.defaults().withMinPeriodsToShorten(0),
                room -> room.equals("Kitchen") ? Duration.ofMinutes(90) : null);
        assertEquals(3, r.baseAlarms(), r.toString());
        assertEquals(0, r.fixedAlarms(), r.toString());
        assertEquals(3.0, r.margin(), r.toString());
    }
}
