package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/**
 * Issue 28, item 1: the quiet period after getting up (a bed mat turning OFF) is its own state, learned from other
 * getting-ups only, not from walks through the bedroom (Ordonez B: the bedroom after the bed mat turned OFF in the
 * morning had "usually at most 11 min" learned from walk-through periods, and the person stayed 26 min and 1 h).
 */
class GettingUpTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);
    private static final Duration BEDROOM = Duration.ofHours(10);

    /** 14 mornings: up at 07:00, 15 min in the bedroom; then five 2 min walks through the bedroom by 08:00. */
    private static LearnedLimits mornings() {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        for (int d = 0; d < 14; d++) {
            l.add(new Sighting(History.at(d, "07:00"), "Bedroom", "Bedroom", "Bedroom", false, false, true));
            l.add(new Sighting(History.at(d, "07:15"), "Hall", "Hall", "Hall", false));
            for (int k = 0; k < 5; k++) {
                l.add(new Sighting(History.at(d, "07:" + (20 + 8 * k)), "Bedroom", "Bedroom", "Bedroom", false));
                l.add(new Sighting(History.at(d, "07:" + (22 + 8 * k)), "Hall", "Hall", "Hall", false));
            }
            l.add(new Sighting(History.at(d, "23:00"), "Bedroom", "Bedroom", "Bedroom", true));
        }
        return new LearnedLimits(l);
    }

    @Test
    void gettingUpIsLearnedFromGettingUpsOnly() {
        Limit up = mornings().limitAfter(new Sighting(History.at(14, "07:00"), "Bedroom", "Bedroom", "Bedroom",
                false, false, true), BEDROOM, History.at(14, "07:00"));
        // 14 getting-ups are too few to shorten the fixed limit (30 needed); mixed with the 70 walks they were not
        assertEquals(BEDROOM, up.limit(), up.explanation());
        assertTrue(up.explanation().contains("after getting up (a bed mat turned off)"), up.explanation());
        assertTrue(up.explanation().contains("only 14 quiet periods support that"), up.explanation());
    }

    @Test
    void aWalkThroughTheBedroomIsNotLearnedFromGettingUps() {
        Limit walk = mornings().limitAfter(new Sighting(History.at(14, "07:20"), "Bedroom", "Bedroom", "Bedroom",
                false), BEDROOM, History.at(14, "07:20"));
        // usual 2 min x 1.5 + 10 min = 13 min, at least the floor of 20 min (mixed with getting up: 15 min, 33 min)
        assertEquals(Duration.ofMinutes(20), walk.limit(), walk.explanation());
        assertTrue(walk.explanation().contains("usually at most 2 min"), walk.explanation());
    }
}
