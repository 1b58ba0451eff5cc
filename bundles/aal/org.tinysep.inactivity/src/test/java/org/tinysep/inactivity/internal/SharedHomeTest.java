package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.device.support.testing.FakeProvider;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 28, item 1 on a two-resident home (session 36), through the platform's Inactivity Recognition: with the
 * configured {@code residents} above 1, a movement in the living room while a seat mat there is ON (known from its
 * first report after a start too) begins a sitting period, whose learned limit is never longer than the fixed one.
 */
class SharedHomeTest {

    private static final Instant DAY0 = Instant.parse("2026-11-02T00:00:00Z");

    private static final class Seat extends FakeProvider<PresenceListener> implements PresenceProvider {
        Seat() {
            super("seat");
        }

        void report(boolean on, boolean first, Instant at) {
            List.copyOf(listeners).forEach(l -> l.presenceChanged(this, on, first, at));
        }

        @Override
        public PresenceKind kind() {
            return PresenceKind.SEAT;
        }

        @Override
        public boolean present() {
            return false;
        }
    }

    private final List<Activity> seen = new ArrayList<>();
    private final Seat seat = new Seat();
    private final Fakes.Movement pir = new Fakes.Movement("pir");

    private static Instant at(int day, int hour, int minute) {
        return DAY0.plus(Duration.ofDays(day).plusHours(hour).plusMinutes(minute));
    }

    /** 14 afternoons: into the living room 14:00, sit down 14:10 for 3 h, up 17:10, kitchen 17:18. */
    private void startWith(int residents) {
        startWith(residents, false);
    }

    /** @param twoAtOnce also 14 nights: in bed 22:00, the kitchen at 22:30 (someone else), up 06:30 */
    private void startWith(int residents, boolean twoAtOnce) {
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, new SleepRule(21, 7, ZoneOffset.UTC),
                LearningSettings.defaults().withMinPeriodsToShorten(0).withResidents(residents));
        for (int d = 0; d < 14 && twoAtOnce; d++) {
            learner.add(new Sighting(at(d, 22, 0), "bedroom", "Bedroom", "Bedroom", true));
            learner.add(new Sighting(at(d, 22, 30), "kitchen", "Kitchen", "Kitchen", false));
            learner.add(new Sighting(at(d + 1, 6, 30), "bedroom", "Bedroom", "Bedroom", false, false, true));
        }
        for (int d = 0; d < 14; d++) {
            learner.add(new Sighting(at(d, 14, 0), "living", "Living room", "Living room", false));
            learner.add(new Sighting(at(d, 14, 10), "living", "Living room", "Living room", false, true));
            learner.add(new Sighting(at(d, 17, 10), "living", "Living room", "Living room", false));
            learner.add(new Sighting(at(d, 17, 18), "kitchen", "Kitchen", "Kitchen", false));
            learner.add(new Sighting(at(d, 18, 0), "kitchen", "Kitchen", "Kitchen", false));
        }
        Fakes.Directory d = new Fakes.Directory();
        d.rooms.put("seat", "living");
        d.rooms.put("pir", "living");
        ActivityFactory f = new ActivityFactory(d, LimitTable.parse(120, "", "living=180"),
                LimitPolicy.learned(new LearnedLimits(learner)), () -> at(20, 15, 0), (a, now) -> seen.add(a));
        seat.connect(f);
        pir.connect(f);
    }

    /** Starts, the seat mat's state after the start ON (14:50), the living-room movement at 15:00: its activity. */
    private Activity movementWhileTheSeatIsOn(int residents, boolean twoAtOnce) {
        startWith(residents, twoAtOnce);
        seat.report(true, true, at(20, 14, 50)); // the seat mat's state after a start: no activity, but ON
        pir.report(at(20, 15, 0));
        assertEquals(1, seen.size());
        return seen.get(0);
    }

    @Test
    void aMovementWhereTheOtherResidentSitsIsASittingPeriod() {
        Activity a = movementWhileTheSeatIsOn(2, false);
        assertEquals(Duration.ofHours(3), a.limit(), a.explanation());
        assertTrue(a.explanation().startsWith("a seat mat in room living is on and the home has 2 residents: "
                + "someone sits there, so the quiet after this activity is a sitting person's; fixed limit of 3 h"),
                a.explanation());
        assertTrue(a.explanation().contains("after sitting down"), a.explanation());
    }

    @Test
    void undeclaredTheHomeIsTakenForTwoFromItsHistoryAtTheFirstActivityAfterAStart() {
        Activity a = movementWhileTheSeatIsOn(0, true);
        assertEquals(Duration.ofHours(3), a.limit(), a.explanation());
        assertTrue(a.explanation().startsWith("a seat mat in room living is on and the home is taken for several "
                + "residents: seen on 14 of the last 16 days of history"), a.explanation());
    }

    @Test
    void undeclaredWithoutSignsOfTwoTheMovementIsGettingUp() {
        Activity a = movementWhileTheSeatIsOn(0, false);
        assertTrue(a.limit().compareTo(Duration.ofMinutes(30)) < 0, "the walk's learned limit: " + a.explanation());
    }

    @Test
    void withOneResidentTheMovementIsGettingUp() {
        Activity a = movementWhileTheSeatIsOn(1, false);
        assertTrue(a.limit().compareTo(Duration.ofMinutes(30)) < 0, "the walk's learned limit: " + a.explanation());
    }

    @Test
    void aftertheSeatMatTurnedOffTheMovementIsAWalkAgain() {
        startWith(2);
        seat.report(true, true, at(20, 14, 40));
        seat.report(false, false, at(20, 14, 50));
        pir.report(at(20, 15, 0));
        Activity a = seen.get(1);
        assertTrue(a.limit().compareTo(Duration.ofMinutes(30)) < 0, "the walk's learned limit: " + a.explanation());
    }
}
