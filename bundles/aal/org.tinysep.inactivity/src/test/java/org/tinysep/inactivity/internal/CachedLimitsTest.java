package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 29, item 1: the learned limit and its explanation are computed once per room, hour and state until the
 * next learning, not per activity; the work per activity does not grow with the history; answers equal the
 * uncached ones.
 */
class CachedLimitsTest {

    private static final LocalDate MONDAY = LocalDate.of(2026, 11, 2);
    private static final Duration FIXED = Duration.ofMinutes(45);

    private static Instant at(int day, int hour, int minute, int second) {
        return MONDAY.plusDays(day).atTime(hour, minute, second).toInstant(ZoneOffset.UTC);
    }

    /** {@code days} days of history: each day bathroom at 14:00, kitchen at 14:05 and 15:00, bed at 22:00. */
    private static HistoryLearner learner(int days) {
        HistoryLearner h = new HistoryLearner(ZoneOffset.UTC, new SleepRule(21, 7, ZoneOffset.UTC),
                LearningSettings.defaults().withMinPeriodsToShorten(0));
        for (int d = 0; d < days; d++) {
            h.add(sighting(at(d, 14, 0, 0), "Bathroom", false));
            h.add(sighting(at(d, 14, 5, 0), "Kitchen", false));
            h.add(sighting(at(d, 15, 0, 0), "Kitchen", false));
            h.add(sighting(at(d, 22, 0, 0), "Bed", true));
        }
        return h;
    }

    private static Sighting sighting(Instant at, String room, boolean inBed) {
        return new Sighting(at, room, room, room.equals("Bed") ? "Bedroom" : room, inBed);
    }

    /** 200 activities on day {@code day} between 14:00 and 14:59, alternating bathroom and kitchen. */
    private static void activities(CachedLimits cached, LearnedLimits plain, int day) {
        for (int i = 0; i < 200; i++) {
            Instant t = at(day, 14, i % 60, (i * 7) % 60);
            Sighting s = sighting(t, i % 2 == 0 ? "Bathroom" : "Kitchen", false);
            Limit c = cached.limitAfter(s, FIXED, t);
            Limit p = plain.limitAfter(s, FIXED, t);
            assertEquals(p, c, "the cached answer must be the computed one for " + s);
        }
    }

    @Test
    void oneComputationPerRoomAndHourWhateverTheHistorysLength() {
        for (int days : new int[] {0, 3, 28}) {
            CachedLimits cached = new CachedLimits(new LearnedLimits(learner(days)));
            activities(cached, new LearnedLimits(learner(days)), days);
            assertEquals(2, cached.computed(), "200 activities in 2 rooms within one hour after " + days
                    + " days of history");
        }
    }

    @Test
    void anotherHourOrStateIsComputedAnew() {
        CachedLimits cached = new CachedLimits(new LearnedLimits(learner(10)));
        LearnedLimits plain = new LearnedLimits(learner(10));
        Instant t = at(10, 14, 0, 0);
        assertEquals(plain.limitAfter(sighting(t, "Kitchen", false), FIXED, t),
                cached.limitAfter(sighting(t, "Kitchen", false), FIXED, t));
        Instant later = at(10, 16, 0, 0);
        assertEquals(plain.limitAfter(sighting(later, "Kitchen", false), FIXED, later),
                cached.limitAfter(sighting(later, "Kitchen", false), FIXED, later));
        Instant night = at(10, 23, 0, 0);
        assertEquals(plain.limitAfter(sighting(night, "Bed", true), FIXED, night),
                cached.limitAfter(sighting(night, "Bed", true), FIXED, night));
        assertEquals(3, cached.computed());
    }

    @Test
    void theNextLearningEmptiesTheCache() {
        HistoryLearner history = learner(10);
        CachedLimits cached = new CachedLimits(new LearnedLimits(history));
        LearnedLimits plain = new LearnedLimits(learner(10));
        assertEquals(history.size(), plain.history().size());
        activities(cached, plain, 10);
        assertEquals(2, cached.computed());
        activities(cached, plain, 11); // a new local day: the learner learns anew
        assertEquals(4, cached.computed());
        history.loaded(); // history read from the log: learns anew at the next question
        plain.history().loaded();
        assertEquals(history.size(), plain.history().size(), "every activity kept once, as without the cache");
        Instant t = at(11, 14, 59, 59);
        Limit c = cached.limitAfter(sighting(t, "Bathroom", false), FIXED, t);
        assertEquals(5, cached.computed());
        assertEquals(plain.limitAfter(sighting(t, "Bathroom", false), FIXED, t), c);
    }

    @Test
    void everyActivityIsStillLearnedFrom() {
        HistoryLearner history = learner(0);
        CachedLimits cached = new CachedLimits(new LearnedLimits(history));
        for (int i = 0; i < 5; i++) { // 5 sightings in the same room an hour apart: none merged
            Instant t = at(0, 8 + i, 0, 0);
            cached.limitAfter(sighting(t, "Kitchen", false), FIXED, t);
            cached.limitAfter(sighting(t.plusSeconds(600), "Bathroom", false), FIXED, t.plusSeconds(600));
        }
        assertEquals(10, history.size());
    }

    /**
     * The cache's own work per activity allocates nothing once an answer is known: its key was a record of three
     * strings, a Duration and the local time as a ZonedDateTime (about 140 bytes and a hash of every field per
     * activity, 15 % of the radio thread). Measured as the bytes this thread allocates beyond the work every
     * activity needs anyway (history add, profile, sleep rule), which the same loop does without the cache.
     */
    @Test
    void aKnownAnswerCostsNoAllocation() {
        int n = 20_000;
        Sighting[] day = new Sighting[n];
        for (int i = 0; i < n; i++) { // rooms of the house, same hour: all answers known after the first two
            Instant t = at(10, 14, (i / 60) % 60, i % 60);
            day[i] = new Sighting(t, i % 2 == 0 ? "Bathroom" : "Kitchen", i % 2 == 0 ? "Bathroom" : "Kitchen",
                    i % 2 == 0 ? "Bathroom" : "Kitchen", false);
        }
        CachedLimits cached = new CachedLimits(new LearnedLimits(learner(10)));
        LearnedLimits plain = new LearnedLimits(learner(10));
        long baseline = Long.MAX_VALUE;
        long withCache = Long.MAX_VALUE;
        for (int round = 0; round < 3; round++) { // the least of three rounds: the first one warms up
            long a = allocated();
            for (Sighting s : day) {
                plain.history().add(s);
                plain.history().profile(s.at());
                plain.history().sleep().asleep(s);
            }
            long b = allocated();
            for (Sighting s : day) {
                cached.limitAfter(s, FIXED, s.at());
            }
            long c = allocated();
            baseline = Math.min(baseline, b - a);
            withCache = Math.min(withCache, c - b);
        }
        double perActivity = (withCache - baseline) / (double) n;
        assertTrue(perActivity < 16, "bytes allocated per activity by the cache beyond the learning itself: "
                + perActivity + " (cache " + withCache / n + ", learning " + baseline / n + ")");
        assertEquals(2, cached.computed());
    }

    /** The answer's place is the local hour and day type, also across a change to summer time. */
    @Test
    void theIndexIsTheLocalHourAndDayType() {
        java.time.ZoneId zurich = java.time.ZoneId.of("Europe/Zurich");
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        for (Instant t = Instant.parse("2026-03-27T00:30:00Z"); t.isBefore(Instant.parse("2026-04-01T00:00:00Z"));
                t = t.plusSeconds(3_600)) {
            java.time.ZonedDateTime z = t.atZone(zurich);
            int weekend = z.getDayOfWeek().getValue() >= 6 ? 1 : 0;
            assertEquals(weekend * 24 + z.getHour(), CachedLimits.index(t, zurich.getRules(), false, false), t.toString());
            assertEquals(((1 * 2 + 0) * 2 + weekend) * 24 + z.getHour(), CachedLimits.index(t, zurich.getRules(), true, false));
            seen.add(CachedLimits.index(t, zurich.getRules(), false, true));
        }
        assertEquals(48, seen.size(), "weekday and weekend hours: " + seen);
    }

    private static long allocated() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean())
                .getThreadAllocatedBytes(Thread.currentThread().getId());
    }
}
