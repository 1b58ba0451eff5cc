package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/**
 * Issue 28 ("never worse than the fixed limits", on delay): a learned limit LONGER than the room's fixed one must
 * be learned from the hours it is used at. Where those hours have too little history and the room's whole day is
 * used instead, the fixed limit holds: a long sit in the afternoon says nothing about the evening.
 */
class LongerFromItsOwnHoursTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);
    private static final Duration FIXED = Duration.ofHours(3);

    /** 7 days: sits down in the living room at 14:00 and stays 5 h; kitchen at 19:00, 19:30 and 20:00. */
    private static LearnedLimits afternoonSitter() {
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        for (int day = 0; day < 7; day++) {
            learner.add(new Sighting(History.at(day, "14:00"), "Living", "Living Room", "Living room", false, true));
            for (String t : new String[] {"19:00", "19:30", "20:00"}) {
                learner.add(new Sighting(History.at(day, t), "Kitchen", "Kitchen", "Kitchen", false));
            }
        }
        return new LearnedLimits(learner);
    }

    private static Limit sitsDownAt(LearnedLimits l, String hhmm) {
        return l.limitAfter(new Sighting(History.at(7, hhmm), "Living", "Living Room", "Living room", false, true),
                FIXED, History.at(7, hhmm));
    }

    @Test
    void aLongerLimitLearnedAtTheseHoursHolds() {
        // 5 h x 1.5 + 10 min = 7 h 40 min, from the 7 afternoons between 13:00 and 16:00
        Limit l = sitsDownAt(afternoonSitter(), "14:00");
        assertEquals(Duration.ofMinutes(460), l.limit(), l.explanation());
    }

    @Test
    void aLongerLimitFromOtherHoursFallsBackToTheFixedOne() {
        // at 10:00 nothing was learned between 09:00 and 12:00: the room's whole day (the 14:00 sits) would give
        // 7 h 40 min; the fixed 3 h holds, and the explanation says why
        Limit l = sitsDownAt(afternoonSitter(), "10:00");
        assertEquals(FIXED, l.limit(), l.explanation());
        assertTrue(l.explanation().startsWith("fixed limit of 3 h for Living Room"), l.explanation());
        assertTrue(l.explanation().contains("would lengthen it to 7 h 40 min"), l.explanation());
        assertTrue(l.explanation().contains("other hours of the day"), l.explanation());
    }
}
