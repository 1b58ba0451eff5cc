package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Issue 28, session 36b: a home whose residents nobody declares is taken for several once its history shows, on
 * enough days, something one person cannot do — activity in another room while a bed mat has been ON for 10 min.
 */
class TwoAtOnceTest {

    private static final Duration FIXED = Duration.ofHours(3);

    private static Sighting bed(int day, String hhmm, boolean on) {
        return new Sighting(History.at(day, hhmm), "Bed", "Bedroom", "Bedroom", on, false, !on);
    }

    private static Sighting kitchen(int day, String hhmm) {
        return new Sighting(History.at(day, hhmm), "Kitchen", "Kitchen", "Kitchen", false);
    }

    /** Nights {@code from} to {@code to} - 1: in bed 22:00, up 06:30, kitchen 06:40; {@code other}: kitchen 22:30. */
    private static List<Sighting> nights(int from, int to, boolean other) {
        List<Sighting> h = new ArrayList<>();
        for (int d = from; d < to; d++) {
            h.add(bed(d, "22:00", true));
            if (other) {
                h.add(kitchen(d, "22:30"));
            }
            h.add(bed(d + 1, "06:30", false));
            h.add(kitchen(d + 1, "06:40"));
        }
        return h;
    }

    @Test
    void activityElsewhereWhileTheBedMatIsOnOnEnoughDaysIsSeveralResidents() {
        TwoAtOnce.Finding f = TwoAtOnce.of(nights(0, 4, true), ZoneOffset.UTC);
        assertEquals(new TwoAtOnce.Finding(5, 4, "on 2026-11-05: activity in Kitchen at 22:30 while the bed mat in "
                + "Bedroom had been on since 22:00"), f);
        assertTrue(f.several(), f.words());
        assertEquals("the home is taken for several residents: seen on 4 of the last 5 days of history, something "
                + "one person cannot do: activity in another room while a bed mat has been on for 10 min or more "
                + "(the latest on 2026-11-05: activity in Kitchen at 22:30 while the bed mat in Bedroom had been on "
                + "since 22:00)", f.words());
    }

    @Test
    void oneResidentGettingUpFirstIsOne() {
        TwoAtOnce.Finding f = TwoAtOnce.of(nights(0, 14, false), ZoneOffset.UTC);
        assertEquals(0, f.seen(), f.words());
        assertFalse(f.several());
        List<Sighting> h = new ArrayList<>(List.of(bed(0, "22:00", true), kitchen(0, "22:05")));
        assertEquals(0, TwoAtOnce.of(h, ZoneOffset.UTC).seen(), "in bed 5 min: sitting on its edge for a moment");
    }

    @Test
    void aLostOffOrRareSignsWeeksApartAreNoSecondResident() {
        List<Sighting> lost = new ArrayList<>(List.of(bed(0, "22:00", true))); // its OFF never came
        for (int d = 1; d < 14; d++) {
            lost.add(kitchen(d, "08:00"));
            lost.add(kitchen(d, "18:00"));
        }
        TwoAtOnce.Finding f = TwoAtOnce.of(lost, ZoneOffset.UTC);
        assertEquals(1, f.seen(), "the bed's ON counts for 12 h only: " + f.words());
        assertFalse(f.several(), f.words());

        List<Sighting> rare = new ArrayList<>(nights(0, 28, false));
        for (int d : new int[] {3, 12, 21}) {
            rare.add(kitchen(d, "23:00"));
        }
        rare.sort(java.util.Comparator.comparing(Sighting::at));
        TwoAtOnce.Finding r = TwoAtOnce.of(rare, ZoneOffset.UTC);
        assertEquals(3, r.seen(), r.words());
        assertFalse(r.several(), "3 of 29 days, fewer than a quarter: " + r.words());
    }

    /** {@link SittingDownTest}'s afternoons, their residents not declared, with {@code nights} of beds added. */
    private static LearnedLimits afternoons(List<Sighting> nights) {
        HistoryLearner l = SittingDownTest.afternoons(LearningSettings.defaults().withMinPeriodsToShorten(0));
        nights.forEach(l::add);
        return new LearnedLimits(l);
    }

    @Test
    void anUndeclaredHomeIsTakenForSeveralFromItsHistory() {
        assertEquals(0, LearningSettings.defaults().residents(), "not declared by default");
        Instant at = History.at(20, "15:00");
        Sighting sit = new Sighting(at, "Living", "Living", "Living room", false, true);
        LearnedLimits two = afternoons(nights(0, 14, true));
        Limit l = two.limitAfter(sit, FIXED, at);
        assertEquals(FIXED, l.limit(), l.explanation());
        assertTrue(l.explanation().startsWith("fixed limit of 3 h for Living: the history would lengthen it to "
                + "4 h 40 min, but the home is taken for several residents: seen on 14 of the last 16 days"),
                l.explanation());
        Limit one = afternoons(nights(0, 14, false)).limitAfter(sit, FIXED, at);
        assertEquals(Duration.ofMinutes(280), one.limit(), "one person's nights: " + one.explanation());
    }

    @Test
    void anUndeclaredHomeReadsTheMatsOnceItIsSeenToBeSeveral() {
        Residents r = new Residents(0);
        r.mat("seat", "Living", false, true);
        Sighting pir = new Sighting(History.at(20, "15:27"), "Living", "Living", "Living room", false);
        assertFalse(r.read(pir).seated(), "nothing seen yet: one resident");
        r.found(TwoAtOnce.of(nights(0, 4, true), ZoneOffset.UTC));
        assertTrue(r.read(pir).seated(), "the mats were kept meanwhile: " + r.words());
        Limit l = r.explain(pir, r.read(pir), new Limit(FIXED, false, "fixed limit of 3 h"));
        assertTrue(l.explanation().startsWith("a seat mat in Living is on and the home is taken for several "
                + "residents: seen on 4 of the last 5 days"), l.explanation());
    }
}
