package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Sleep and night: going to bed switches to the sleep state with its own learned limits; getting up at night and
 * not returning is detected by the limit of the room the person went to, learned for the night, not the night's.
 */
class SleepAndNightTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);

    @Test
    void theSleepRule() {
        assertTrue(SLEEP.asleep(new Sighting(History.at(0, "23:00"), "b", "Bed", "Bedroom", false)));
        assertTrue(SLEEP.asleep(new Sighting(History.at(0, "05:00"), "b", "Bed", "Bedroom", false)));
        assertFalse(SLEEP.asleep(new Sighting(History.at(0, "15:00"), "b", "Bed", "Bedroom", false)),
                "the bedroom by day is awake");
        assertFalse(SLEEP.asleep(new Sighting(History.at(0, "03:00"), "w", "WC", "Bathroom", false)),
                "up at night in the bathroom is awake");
        assertTrue(SLEEP.asleep(new Sighting(History.at(0, "15:00"), "s", "Sofa", "Living room", true)),
                "a bed mat ON is sleep at any hour");
        assertFalse(new SleepRule(1, 5, ZoneOffset.UTC).night(History.at(0, "23:00")));
        assertTrue(new SleepRule(1, 5, ZoneOffset.UTC).night(History.at(0, "02:00")));
    }

    /** 14 nights: to bed at 23:00, bathroom at 03:00 for 8 min, back to bed, up at 07:00 in the kitchen. */
    private static HistoryLearner nights() {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults().withMinPeriodsToShorten(0));
        for (int d = 0; d < 14; d++) {
            new History().in("Bed", d, "23:00").in("Bathroom", d + 1, "03:00").in("Bed", d + 1, "03:08")
                    .in("Kitchen", d + 1, "07:00").in("Kitchen", d + 1, "07:40").sightings().forEach(l::add);
        }
        return l;
    }

    @Test
    void sleepHasItsOwnLearnedLimitAndTheNightBathroomAMuchShorterOne() {
        LearnedLimits limits = new LearnedLimits(nights());
        Limit bed = limits.limitAfter(new Sighting(History.at(20, "23:00"), "Bed", "Bed", "Bedroom", false),
                Duration.ofHours(10), History.at(20, "23:00"));
        assertTrue(bed.asleep());
        assertEquals(Duration.ofHours(4).multipliedBy(3).dividedBy(2).plusMinutes(10), bed.limit(),
                "the longest sleep stretch seen (23:00-03:00) x 1.5 + 10 min: " + bed.explanation());
        assertTrue(bed.explanation().contains("asleep in Bed"), bed.explanation());

        Limit bath = limits.limitAfter(new Sighting(History.at(21, "03:00"), "Bathroom", "Bathroom", "Bathroom",
                false), Duration.ofMinutes(45), History.at(21, "03:00"));
        assertFalse(bath.asleep());
        assertEquals(Duration.ofMinutes(22), bath.limit(), "8 min x 1.5 + 10 min: " + bath.explanation());
        assertTrue(bath.explanation().startsWith("usually at most 8 min between 02:00 and 05:00 in Bathroom, "
                + "from 14 days"), bath.explanation());
        assertTrue(bath.limit().multipliedBy(10).compareTo(bed.limit()) < 0, "much faster than the night's limit");
    }

    @Test
    void beforeEnoughHistoryTheFixedLimitsApplyAndSaySo() {
        HistoryLearner empty = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        Limit bath = new LearnedLimits(empty).limitAfter(new Sighting(History.at(0, "03:00"), "Bathroom",
                "Bathroom", "Bathroom", false), Duration.ofMinutes(45), History.at(0, "03:00"));
        assertEquals(Duration.ofMinutes(45), bath.limit());
        assertEquals("fixed limit of 45 min for Bathroom: fewer than 7 days of history for this room yet, so "
                + "nothing is learned", bath.explanation());
    }

    @Test
    void quietPeriodsWhileTheFlatWasEmptyAreNotLearned() {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        for (int d = 0; d < 10; d++) {
            new History().in("Hall", d, "09:00").in("Hall", d, "12:00").sightings().forEach(l::add);
            l.occupancy(true, History.at(d, "09:10"));
            l.occupancy(false, History.at(d, "11:59"));
        }
        assertTrue(l.profile(History.at(11, "00:00")).learned("Hall", "Hall", false, History.at(11, "09:00"))
                .isEmpty(), "the 3 h were an absence, not a quiet time at home");
        List<Gap> none = QuietGaps.of(new History().in("Hall", 0, "09:00").in("Hall", 0, "12:00").sightings(),
                List.of(new QuietGaps.Away(History.at(0, "09:10"), History.at(0, "11:59"))), SLEEP);
        assertTrue(none.isEmpty());
    }

    @Test
    void sightingsInTheSameRoomWithinAMinuteAreKeptAsOne() {
        HistoryLearner l = new HistoryLearner(ZoneOffset.UTC, SLEEP, LearningSettings.defaults());
        for (int s = 0; s < 600; s += 2) {
            l.add(new Sighting(History.at(0, "10:00").plusSeconds(s), "Kitchen", "Kitchen", "Kitchen", false));
        }
        assertEquals(1, l.size(), "a motion sensor repeating every 2 s");
    }
}
