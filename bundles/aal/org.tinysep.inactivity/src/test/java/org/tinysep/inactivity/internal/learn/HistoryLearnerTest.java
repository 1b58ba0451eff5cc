package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/** When the learner learns anew: once a day, or when history was read from the log; not per late sighting. */
class HistoryLearnerTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);

    private static HistoryLearner learnerWithTenAfternoons() {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        History h = new History();
        for (int d = 0; d < 10; d++) {
            h.in("Bathroom", d, "14:00").in("Kitchen", d, "14:20");
        }
        h.sightings().forEach(l::add);
        l.loaded();
        return l;
    }

    @Test
    void aLateSightingDoesNotMakeTheProfileLearnAnewButTheNextDaysLearningSortsItIn() {
        HistoryLearner l = learnerWithTenAfternoons();
        QuietProfile today = l.profile(History.at(10, "15:00"));
        l.add(new Sighting(History.at(10, "14:50"), "Kitchen", "Kitchen", "Kitchen", false));
        l.add(new Sighting(History.at(10, "14:30"), "Bathroom", "Bathroom", "Bathroom", false)); // 20 min late
        assertSame(today, l.profile(History.at(10, "15:01")), "learned anew for a late sighting");

        QuietProfile tomorrow = l.profile(History.at(11, "09:00"));
        assertNotSame(today, tomorrow);
        assertEquals(11, tomorrow.historyDays(), "the late sightings are part of the next day's learning");
    }

    @Test
    void historyReadFromTheLogIsLearnedAtTheNextQuestion() {
        HistoryLearner l = learnerWithTenAfternoons();
        QuietProfile before = l.profile(History.at(10, "15:00"));
        l.add(new Sighting(History.at(9, "10:00"), "Hall", "Hall", "Hall", false));
        l.loaded();
        assertNotSame(before, l.profile(History.at(10, "15:01")));
    }
}
