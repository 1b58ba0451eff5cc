package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** Learning limits per room and hour from quiet periods, with cold start, floor, fence and day types. */
class QuietProfileTest {

    private static final SleepRule SLEEP = new SleepRule(21, 7, ZoneOffset.UTC);
    private static final LearningSettings SET = LearningSettings.defaults();

    /** Each day: bathroom at 14:00, then kitchen {@code minutes} later. */
    private static History bathroomAfternoons(int days, int minutes) {
        History h = new History();
        for (int d = 0; d < days; d++) {
            h.in("Bathroom", d, "14:00").in("Kitchen", d, String.format("14:%02d", minutes));
        }
        return h;
    }

    private static QuietProfile profile(History h, LearningSettings s) {
        return new QuietProfile(QuietGaps.of(h.sightings(), List.of(), SLEEP), ZoneOffset.UTC, s);
    }

    @Test
    void nothingIsLearnedBeforeMinDaysOfHistory() {
        Optional<Learned> six = profile(bathroomAfternoons(6, 20), SET)
                .learned("Bathroom", "Bathroom", false, History.at(20, "14:10"));
        assertTrue(six.isEmpty(), "6 of 7 days: cold start");
        Optional<Learned> seven = profile(bathroomAfternoons(7, 20), SET)
                .learned("Bathroom", "Bathroom", false, History.at(20, "14:10"));
        assertTrue(seven.isPresent(), "7 days: learned");
    }

    @Test
    void theLimitIsTheUsualLongestQuietTimesMarginPlusPadAndExplainsItself() {
        Learned l = profile(bathroomAfternoons(21, 20), SET)
                .learned("Bathroom", "Bathroom", false, History.at(30, "14:30")).orElseThrow();
        assertEquals(Duration.ofMinutes(20), l.usual());
        assertEquals(Duration.ofMinutes(40), l.limit(), "20 min x 1.5 + 10 min");
        assertEquals(21, l.days());
        assertEquals("usually at most 20 min between 13:00 and 16:00 in Bathroom, from 21 days (21 quiet periods); "
                + "limit 40 min = usual x 1.5 + 10 min, at least 20 min", l.explain(SET));
    }

    @Test
    void neverBelowTheFloor() {
        Learned l = profile(bathroomAfternoons(10, 2), SET)
                .learned("Bathroom", "Bathroom", false, History.at(30, "14:00")).orElseThrow();
        assertEquals(Duration.ofMinutes(20), l.limit(), "2 min x 1.5 + 10 = 13 min, floor 20 min");
    }

    @Test
    void oneFreakQuietPeriodCannotLiftTheLimitByHours() {
        History h = bathroomAfternoons(13, 20);
        h.in("Bathroom", 13, "14:00").in("Kitchen", 13, "20:00"); // 6 h: an outage, an unseen absence
        Learned l = profile(h, SET).learned("Bathroom", "Bathroom", false, History.at(30, "14:00")).orElseThrow();
        assertEquals(Duration.ofMinutes(20), l.usual(), "above Tukey's far-out fence of the daily maxima");
        History few = bathroomAfternoons(5, 20);
        few.in("Bathroom", 5, "14:00").in("Kitchen", 5, "20:00");
        LearningSettings three = new LearningSettings(3, 28, 1.5, Duration.ofMinutes(10), Duration.ofMinutes(20),
                Duration.ofHours(12), 1);
        Learned max = profile(few, three).learned("Bathroom", "Bathroom", false, History.at(30, "14:00"))
                .orElseThrow();
        assertEquals(Duration.ofHours(6), max.usual(), "with 6 days the fence is not trusted: the maximum");
    }

    @Test
    void hoursFarFromTheQuestionDoNotCount() {
        History h = bathroomAfternoons(10, 20);
        for (int d = 0; d < 10; d++) {
            h.in("Bathroom", d, "08:00").in("Kitchen", d, "09:30"); // a long morning bath
        }
        Learned afternoon = profile(h, SET).learned("Bathroom", "Bathroom", false, History.at(30, "15:00"))
                .orElseThrow();
        assertEquals(Duration.ofMinutes(20), afternoon.usual());
        Learned morning = profile(h, SET).learned("Bathroom", "Bathroom", false, History.at(30, "09:00"))
                .orElseThrow();
        assertEquals(Duration.ofMinutes(90), morning.usual());
        assertTrue(morning.explain(SET).contains("between 08:00 and 11:00"), morning.explain(SET));
    }

    @Test
    void aTimeOfDayWithoutEnoughHistoryFallsBackToTheRoomAtAnyTime() {
        Learned night = profile(bathroomAfternoons(10, 20), SET)
                .learned("Bathroom", "Bathroom", false, History.at(30, "03:00")).orElseThrow();
        assertEquals(Duration.ofMinutes(20), night.usual());
        assertTrue(night.explain(SET).contains("at any time of day"), night.explain(SET));
    }

    @Test
    void dayTypesAreSplitOnlyWhereBothHaveEnoughDays() {
        History h = new History();
        for (int d = 0; d < 28; d++) {
            boolean weekend = d % 7 >= 5;
            h.in("Living", d, "15:00").in("Kitchen", d, weekend ? "17:00" : "15:30");
        }
        LearningSettings s = new LearningSettings(4, 28, 1.5, Duration.ofMinutes(10), Duration.ofMinutes(20),
                Duration.ofHours(12), 1);
        Learned saturday = profile(h, s).learned("Living", "Living", false, History.at(33, "15:00")).orElseThrow();
        assertEquals(Duration.ofHours(2), saturday.usual());
        assertTrue(saturday.explain(s).contains("at weekends"), saturday.explain(s));
        Learned monday = profile(h, s).learned("Living", "Living", false, History.at(35, "15:00")).orElseThrow();
        assertEquals(Duration.ofMinutes(30), monday.usual());
        assertTrue(monday.explain(s).contains("on weekdays"), monday.explain(s));
        History twoWeeks = new History();
        for (int d = 0; d < 14; d++) {
            twoWeeks.in("Living", d, "15:00").in("Kitchen", d, d % 7 >= 5 ? "17:00" : "15:30");
        }
        Learned pooled = profile(twoWeeks, SET).learned("Living", "Living", false, History.at(35, "15:00"))
                .orElseThrow();
        assertEquals(Duration.ofHours(2), pooled.usual(), "4 weekend days < 7: one pool, the weekend's nap counts");
        assertTrue(!pooled.explain(SET).contains("weekdays"), pooled.explain(SET));
    }
}
