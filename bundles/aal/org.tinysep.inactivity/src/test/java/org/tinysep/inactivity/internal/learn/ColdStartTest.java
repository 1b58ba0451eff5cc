package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/** Issue 11: the cold start degrades gracefully: a few days of history already move the limit, without a switch. */
class ColdStartTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);

    /** Each day: bathroom at 14:00, kitchen 5 minutes later (the bathroom's quiet periods last 5 min). */
    private static LearnedLimits history(int days) {
        // the blend itself, without the issue-28 rule (NeverWorseTest): any number of periods may shorten a limit
        LearningSettings s = LearningSettings.defaults();
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, SLEEP, new LearningSettings(s.minDays(),
                s.historyDays(), s.margin(), s.pad(), s.floor(), s.ceiling(), s.halfWindow(), 0));
        for (int d = 0; d < days; d++) {
            learner.add(new Sighting(History.at(d, "14:00"), "Bathroom", "Bathroom", "Bathroom", false));
            learner.add(new Sighting(History.at(d, "14:05"), "Kitchen", "Kitchen", "Kitchen", false));
        }
        return new LearnedLimits(learner);
    }

    private static Limit bathroomLimit(int days) {
        return history(days).limitAfter(new Sighting(History.at(days, "14:00"), "Bathroom", "Bathroom", "Bathroom",
                false), Duration.ofMinutes(45), History.at(days, "14:00"));
    }

    @Test
    void threeDaysOfHistoryAlreadyMoveTheFixedLimitTowardsTheLearnedOne() {
        // learned from 3 days: 5 min x 1.5 + 10 min = 17.5 -> floor 20 min; Z = sqrt(3/7) = 0.65
        // -> 0.65 x 20 + 0.35 x 45 = 28.8 min (was: the fixed 45 min until 7 days)
        Limit l = bathroomLimit(3);
        assertEquals(Duration.ofSeconds(Math.round(Math.sqrt(3.0 / 7) * 1200 + (1 - Math.sqrt(3.0 / 7)) * 2700)),
                l.limit(), l.explanation());
        assertTrue(l.explanation().contains("65 % of what 3 days of history taught"), l.explanation());
        assertTrue(l.explanation().contains("35 % of the fixed limit of 45 min for Bathroom"), l.explanation());
    }

    @Test
    void todaysFirstMinutesAreNoDayOfHistory() {
        // a new installation (or a thesis scenario) on its first day: its own minutes of activity must not shorten
        // the fixed limit before a whole day of history exists
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        learner.add(new Sighting(History.at(0, "14:00"), "Bathroom", "Bathroom", "Bathroom", false));
        learner.add(new Sighting(History.at(0, "14:05"), "Kitchen", "Kitchen", "Kitchen", false));
        Limit l = new LearnedLimits(learner).limitAfter(new Sighting(History.at(0, "14:10"), "Bathroom", "Bathroom",
                "Bathroom", false), Duration.ofMinutes(45), History.at(0, "14:10"));
        assertEquals(Duration.ofMinutes(45), l.limit(), l.explanation());
    }

    @Test
    void theLimitApproachesTheLearnedOneDayByDayWithoutASwitch() {
        Duration previous = Duration.ofMinutes(45);
        for (int days = 1; days <= 7; days++) {
            Duration now = bathroomLimit(days).limit();
            assertTrue(now.compareTo(previous) < 0, days + " days: " + now + " not below " + previous);
            assertTrue(now.compareTo(Duration.ofMinutes(20)) >= 0, "never below the floor: " + now);
            previous = now;
        }
        assertEquals(Duration.ofMinutes(20), previous, "7 days: fully learned");
    }
}
