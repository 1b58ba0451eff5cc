package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/**
 * Issue 11, session 21: a quiet period that a seat mat turning ON began (the person sat down: present and resting)
 * is learned apart from the room's other quiet periods (the person moving about). Hours of sitting still must not
 * lengthen the limit after getting up, and short stretches of moving about must not shorten the limit of sitting.
 */
class SittingDownTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);

    /** 14 afternoons: into the living room 14:00, sit down 14:10 for 3 h, up 17:10, 8 min later to the kitchen. */
    private static HistoryLearner afternoons() {
        return afternoons(LearningSettings.defaults().withMinPeriodsToShorten(0));
    }

    /** The afternoons of {@link #afternoons()} learned with {@code settings}. */
    static HistoryLearner afternoons(LearningSettings settings) {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, settings);
        for (int d = 0; d < 14; d++) {
            l.add(new Sighting(History.at(d, "14:00"), "Living", "Living", "Living room", false));
            l.add(new Sighting(History.at(d, "14:10"), "Living", "Living", "Living room", false, true));
            l.add(new Sighting(History.at(d, "17:10"), "Living", "Living", "Living room", false));
            l.add(new Sighting(History.at(d, "17:18"), "Kitchen", "Kitchen", "Kitchen", false));
            l.add(new Sighting(History.at(d, "18:00"), "Kitchen", "Kitchen", "Kitchen", false));
        }
        return l;
    }

    @Test
    void sittingDownHasItsOwnLimitAndGettingUpAShortOne() {
        LearnedLimits limits = new LearnedLimits(afternoons());
        Limit sat = limits.limitAfter(new Sighting(History.at(20, "15:00"), "Living", "Living", "Living room",
                false, true), Duration.ofHours(3), History.at(20, "15:00"));
        assertEquals(Duration.ofHours(3).multipliedBy(3).dividedBy(2).plusMinutes(10), sat.limit(),
                "3 h of sitting x 1.5 + 10 min: " + sat.explanation());
        assertTrue(sat.explanation().startsWith("usually at most 3 h between 14:00 and 17:00 after sitting down"
                + " (a seat mat turned on) in Living, from 14 days"), sat.explanation());

        Limit up = limits.limitAfter(new Sighting(History.at(20, "14:00"), "Living", "Living", "Living room",
                false), Duration.ofHours(3), History.at(20, "14:00"));
        assertEquals(Duration.ofMinutes(25), up.limit(),
                "10 min (14:00-14:10) x 1.5 + 10 min, not the 3 h of sitting: " + up.explanation());
        assertTrue(up.explanation().startsWith("usually at most 10 min between 13:00 and 16:00 in Living"),
                up.explanation());
    }

    @Test
    void aSeatMatInBedroomAtNightIsSleepNotSitting() {
        assertTrue(SLEEP.asleep(new Sighting(History.at(0, "23:00"), "b", "Bed", "Bedroom", false, true)));
        LearnedLimits limits = new LearnedLimits(afternoons());
        Limit l = limits.limitAfter(new Sighting(History.at(20, "23:00"), "b", "Bed", "Bedroom", false, true),
                Duration.ofHours(10), History.at(20, "23:00"));
        assertTrue(l.asleep(), l.explanation());
        assertTrue(!l.explanation().contains("sitting down"), l.explanation());
    }
}
