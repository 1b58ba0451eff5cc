package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;

/** The inactivity algorithm in virtual time, with the default limits of the configuration. */
class InactivityLogicTest {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");
    private static final LimitTable LIMITS = LimitTable.parse(120,
            new InactivityConfigDefaults().typeLimits(), "");
    private static final Room BEDROOM = new Room("r-bed", "Bedroom", "Bedroom", Set.of());
    private static final Room BATHROOM = new Room("r-bath", "Bathroom", "Bathroom", Set.of());
    private static final Room KITCHEN = new Room("r-kit", "Kitchen", "Kitchen", Set.of());
    private static final Room LIVING = new Room("r-liv", "Living room", "Living room", Set.of());
    private static final Room HALL = new Room("r-hall", "Hall", "Hall", Set.of());

    private final InactivityLogic logic = new InactivityLogic(Duration.ofMinutes(120), T0);
    private final List<String> transitions = new ArrayList<>();
    private Instant clock = T0;

    private static Instant at(int hour, int minute) {
        return T0.plusSeconds((hour - 7) * 3600L + minute * 60L);
    }

    private static Activity in(Room room, Instant at) {
        return new Activity(room.uid(), room.name(), "movement by " + room.name() + " sensor", at,
                LIMITS.limitFor(room));
    }

    /** Ticks every second up to {@code until}, recording every change. */
    private void runUntil(Instant until) {
        while (clock.isBefore(until)) {
            clock = clock.plusSeconds(1);
            logic.tick(clock).ifPresent(s -> transitions.add(s + "@" + clock));
        }
    }

    private void doAt(Instant t, Activity a) {
        runUntil(t);
        logic.activity(a).ifPresent(s -> transitions.add(s + "@" + t));
    }

    @Test
    void aNormalDayRaisesNoAlert() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        doAt(at(7, 0), in(BEDROOM, at(7, 0)));
        doAt(at(7, 5), in(HALL, at(7, 5)));
        doAt(at(7, 6), in(BATHROOM, at(7, 6)));
        doAt(at(7, 40), in(KITCHEN, at(7, 40)));           // 34 min in the bathroom: under 45
        doAt(at(8, 50), in(LIVING, at(8, 50)));            // 70 min in the kitchen: under 90
        doAt(at(11, 40), in(KITCHEN, at(11, 40)));         // 170 min reading: under 180
        doAt(at(12, 30), in(LIVING, at(12, 30)));
        doAt(at(15, 0), in(LIVING, at(15, 0)));
        doAt(at(17, 45), in(KITCHEN, at(17, 45)));
        doAt(at(18, 30), in(LIVING, at(18, 30)));
        doAt(at(21, 0), in(BATHROOM, at(21, 0)));
        doAt(at(21, 20), in(BEDROOM, at(21, 20)));
        runUntil(T0.plus(Duration.ofHours(24)));           // 9 h 40 min of sleep: under 10 h
        assertEquals(List.of(), transitions);
        assertEquals(InactivityState.WATCHING, logic.state());
    }

    @Test
    void aCollapseInTheBathroomAlertsExactlyOnceAtLastActivityPlusLimit() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        doAt(at(7, 0), in(BEDROOM, at(7, 0)));
        doAt(at(9, 0), in(KITCHEN, at(9, 0)));
        doAt(at(9, 10), in(BATHROOM, at(9, 10)));
        runUntil(at(13, 0));
        assertEquals(List.of("ALERT@" + at(9, 55)), transitions);
        InactivityAlert alert = logic.alert().orElseThrow();
        assertEquals("r-bath", alert.roomUid());
        assertEquals("Bathroom", alert.roomName());
        assertEquals("movement by Bathroom sensor", alert.lastActivity());
        assertEquals(at(9, 10), alert.lastActivityAt());
        assertEquals(at(9, 55), alert.raisedAt());
    }

    @Test
    void leavingTheFlatStopsWatching() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        doAt(at(8, 0), in(HALL, at(8, 0)));
        runUntil(at(8, 10));
        assertEquals(Optional.of(InactivityState.NOT_WATCHING), logic.occupancy(Occupancy.UNOCCUPIED, at(8, 10)));
        runUntil(at(20, 0));
        assertEquals(List.of(), transitions);
        assertEquals(Optional.empty(), logic.deadline());
    }

    @Test
    void theNextActivityClearsTheAlertAndALaterExpiryAlertsAgain() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        doAt(at(7, 0), in(HALL, at(7, 0)));
        runUntil(at(7, 45));
        doAt(at(7, 45), in(KITCHEN, at(7, 45)));
        assertEquals(InactivityState.WATCHING, logic.state());
        assertEquals(Optional.empty(), logic.alert());
        runUntil(at(10, 0));
        assertEquals(List.of("ALERT@" + at(7, 30), "WATCHING@" + at(7, 45), "ALERT@" + at(9, 15)), transitions);
        assertEquals("Kitchen", logic.alert().orElseThrow().roomName());
    }

    @Test
    void watchingStartsWhenTheFlatBecomesOccupiedNotAtAnOldActivity() {
        logic.activity(in(HALL, at(7, 0)));                  // seen before anybody was known to be home
        runUntil(at(9, 0));
        assertEquals(List.of(), transitions, "not watching while occupancy is unknown");
        logic.occupancy(Occupancy.OCCUPIED, at(9, 0));
        assertEquals(Optional.of(at(9, 30)), logic.deadline(), "hall limit counted from the arrival");
    }

    @Test
    void withoutAnyActivityTheDefaultLimitRunsFromTheStartOfWatching() {
        logic.occupancy(Occupancy.OCCUPIED, at(8, 0));
        runUntil(at(11, 0));
        assertEquals(List.of("ALERT@" + at(10, 0)), transitions);
        assertEquals("no activity since watching began", logic.alert().orElseThrow().lastActivity());
    }

    @Test
    void anOlderReportDoesNotReplaceTheLastActivity() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        logic.activity(in(BEDROOM, at(8, 0)));
        assertEquals(Optional.empty(), logic.rebase(at(8, 0)), "the platform clock did not go back");
        logic.activity(in(HALL, at(7, 59))); // a late delivery
        assertEquals("Bedroom", logic.lastActivity().orElseThrow().roomName());
        assertTrue(logic.deadline().orElseThrow().isAfter(at(17, 0)));
    }

    @Test
    void anActivityWithoutARoomAtTheSameInstantKeepsTheRoomsInEitherOrder() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        Activity pendant = new Activity("", "unknown room", "Anna's pendant moved", at(8, 0), Duration.ofHours(2));
        logic.activity(in(KITCHEN, at(8, 0)));
        logic.activity(pendant); // the pendant's report of the same moment, taken second
        assertEquals("Kitchen", logic.lastActivity().orElseThrow().roomName());
        assertEquals(at(8, 0).plus(LIMITS.limitFor(KITCHEN)), logic.deadline().orElseThrow(), "the kitchen's limit");

        InactivityLogic other = new InactivityLogic(Duration.ofMinutes(120), T0);
        other.occupancy(Occupancy.OCCUPIED, T0);
        other.activity(pendant); // taken first
        other.activity(in(KITCHEN, at(8, 0)));
        assertEquals(logic.lastActivity(), other.lastActivity(), "the same last activity in either order");

        Activity later = new Activity("", "unknown room", "Anna's pendant moved", at(8, 1), Duration.ofHours(2));
        logic.activity(later); // a later one without a room still counts
        assertEquals(later, logic.lastActivity().orElseThrow());
    }

    @Test
    void aClockThatWentBackIsRebasedAndTheOlderReportCounts() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        logic.activity(in(BEDROOM, at(20, 0)));
        assertEquals(Optional.of(at(20, 0)), logic.rebase(at(8, 0)), "the clock came back from 20:00");
        assertEquals(Optional.of(at(8, 0).plusSeconds(600 * 60)), logic.deadline(), "counted from now");
        logic.activity(in(HALL, at(8, 1)));
        assertEquals("Hall", logic.lastActivity().orElseThrow().roomName());
        assertEquals(Optional.of(at(8, 31)), logic.deadline());
        assertEquals(Optional.empty(), logic.rebase(at(8, 2)), "once re-based, nothing is in the future");
    }

    /** Issue 25, item 2: Flat Occupancy going away (UNKNOWN) is no one leaving: an open alert stays. */
    @Test
    void flatOccupancyGoingAwayDoesNotEndAnAlert() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        doAt(at(9, 10), in(BATHROOM, at(9, 10)));
        runUntil(at(9, 55));
        assertEquals(InactivityState.ALERT, logic.state());
        assertEquals(Optional.empty(), logic.occupancy(Occupancy.UNKNOWN, at(9, 56)));
        assertEquals(InactivityState.ALERT, logic.state());
        assertEquals(at(9, 55), logic.alert().orElseThrow().raisedAt());
        assertEquals(Optional.empty(), logic.occupancy(Occupancy.OCCUPIED, at(9, 57)), "Flat Occupancy back");
        assertEquals(InactivityState.ALERT, logic.state());
        assertEquals(Optional.of(InactivityState.NOT_WATCHING), logic.occupancy(Occupancy.UNOCCUPIED, at(10, 0)),
                "a real decision that someone left still ends it");
        assertEquals(Optional.empty(), logic.alert());
    }

    /** Issue 25, item 2: real activity still clears the alert while Flat Occupancy is gone. */
    @Test
    void activityStillClearsAnAlertKeptWhileFlatOccupancyIsGone() {
        logic.occupancy(Occupancy.OCCUPIED, T0);
        doAt(at(9, 10), in(BATHROOM, at(9, 10)));
        runUntil(at(9, 55));
        logic.occupancy(Occupancy.UNKNOWN, at(9, 56));
        doAt(at(10, 0), in(KITCHEN, at(10, 0)));
        assertEquals(InactivityState.WATCHING, logic.state());
        assertEquals(Optional.empty(), logic.alert());
    }
}
