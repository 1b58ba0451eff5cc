package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

/** Issue 28 item 2: getting out of bed at night ends sleep, also in the bedroom. */
class AwakeAtNightTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);

    private static Sighting bedroom(String hhmm, boolean inBed, boolean up) {
        return new Sighting(History.at(0, hhmm), "Bedroom", "Bedroom", "Bedroom", inBed, false, up);
    }

    @Test
    void theBedMatTurningOffEndsSleep() {
        assertTrue(SLEEP.asleep(bedroom("23:00", true, false)), "in bed");
        assertTrue(SLEEP.asleep(bedroom("03:00", false, false)), "bedroom at night, nothing says up: asleep");
        assertFalse(SLEEP.asleep(bedroom("03:00", false, true)), "out of bed at 03:00: awake");
    }

    @Test
    void anAwakeNightInTheBedroomGetsTheAwakeLimitNotTheNights() {
        // 14 nights: to bed 23:00, up at 03:00 (mat off) for 10 min in the bedroom, back to bed, kitchen at 07:00
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults()
                .withMinPeriodsToShorten(0));
        for (int d = 0; d < 14; d++) {
            l.add(new Sighting(History.at(d, "23:00"), "Bedroom", "Bedroom", "Bedroom", true, false));
            l.add(new Sighting(History.at(d + 1, "03:00"), "Bedroom", "Bedroom", "Bedroom", false, false, true));
            l.add(new Sighting(History.at(d + 1, "03:10"), "Bedroom", "Bedroom", "Bedroom", true, false));
            l.add(new Sighting(History.at(d + 1, "07:00"), "Kitchen", "Kitchen", "Kitchen", false, false));
        }
        Limit up = new LearnedLimits(l).limitAfter(new Sighting(History.at(15, "03:00"), "Bedroom", "Bedroom",
                "Bedroom", false, false, true), Duration.ofHours(10), History.at(15, "03:00"));
        assertFalse(up.asleep(), up.explanation());
        assertEquals(Duration.ofMinutes(25), up.limit(), "10 min x 1.5 + 10 min, not the night's: " + up.explanation());
    }
}
