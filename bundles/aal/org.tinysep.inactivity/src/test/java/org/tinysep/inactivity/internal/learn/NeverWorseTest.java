package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/** Issue 28: with thin history a learned limit never undercuts the fixed (thesis) limit. */
class NeverWorseTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);
    private static final Duration FIXED = Duration.ofMinutes(45);

    /** Each day: bathroom at 14:00 and kitchen 5 minutes later, {@code perDay} times (an hour apart). */
    private static Limit bathroomLimit(int days, int perDay, int minPeriods) {
        LearningSettings d = LearningSettings.defaults();
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, SLEEP, new LearningSettings(d.minDays(),
                d.historyDays(), d.margin(), d.pad(), d.floor(), d.ceiling(), d.halfWindow(), minPeriods));
        for (int day = 0; day < days; day++) {
            for (int i = 0; i < perDay; i++) {
                learner.add(new Sighting(History.at(day, (13 + i) + ":00"), "Bathroom", "Bathroom", "Bathroom", false));
                learner.add(new Sighting(History.at(day, (13 + i) + ":05"), "Kitchen", "Kitchen", "Kitchen", false));
            }
        }
        return new LearnedLimits(learner).limitAfter(new Sighting(History.at(days, "14:00"), "Bathroom", "Bathroom",
                "Bathroom", false), FIXED, History.at(days, "14:00"));
    }

    @Test
    void theDefaultNeedsThirtyPeriodsToShorten() {
        assertEquals(30, LearningSettings.defaults().minPeriodsToShorten());
    }

    @Test
    void tenPeriodsDoNotShortenTheFixedLimit() {
        // 10 days x 1 period: learned 20 min (5 min x 1.5 + 10, floor 20) from 10 periods < 30 -> the fixed 45 min
        Limit l = bathroomLimit(10, 1, 30);
        assertEquals(FIXED, l.limit(), l.explanation());
        assertTrue(l.explanation().contains("only 10 quiet periods support that"), l.explanation());
        assertTrue(l.explanation().contains("fixed limit of 45 min for Bathroom"), l.explanation());
    }

    @Test
    void enoughPeriodsShortenIt() {
        // 10 days x 3 periods around 14:00 = 30 periods: the learned 20 min holds
        Limit l = bathroomLimit(10, 3, 30);
        assertEquals(Duration.ofMinutes(20), l.limit(), l.explanation());
    }

    @Test
    void theBlendOfAColdStartIsHeldToo() {
        // 3 days: the blend would give 29 min; 3 periods < 30 -> 45 min; without the rule (0) the blend holds
        assertEquals(FIXED, bathroomLimit(3, 1, 30).limit());
        assertTrue(bathroomLimit(3, 1, 0).limit().compareTo(FIXED) < 0);
    }

    @Test
    void aLongerLearnedLimitNeedsNoSupport() {
        // quiet 60 min in the bathroom on 7 days: learned 60 x 1.5 + 10 = 100 min > 45 min, from only 7 periods
        LearningSettings d = LearningSettings.defaults();
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, SLEEP, d);
        for (int day = 0; day < 7; day++) {
            learner.add(new Sighting(History.at(day, "14:00"), "Bathroom", "Bathroom", "Bathroom", false));
            learner.add(new Sighting(History.at(day, "15:00"), "Kitchen", "Kitchen", "Kitchen", false));
        }
        Limit l = new LearnedLimits(learner).limitAfter(new Sighting(History.at(7, "14:00"), "Bathroom", "Bathroom",
                "Bathroom", false), FIXED, History.at(7, "14:00"));
        assertEquals(Duration.ofMinutes(100), l.limit(), l.explanation());
    }
}
