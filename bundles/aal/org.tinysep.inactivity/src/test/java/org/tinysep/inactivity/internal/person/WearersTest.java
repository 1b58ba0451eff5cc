package org.tinysep.inactivity.internal.person;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.MovementSummary;

/** The attribution rule and "not worn" (README "Activity per person"). */
class WearersTest {

    private static final Instant T0 = Instant.parse("2026-11-29T10:00:00Z");
    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC);
    private final Wearers wearers = new Wearers(WearerSettings.defaults(), HH_MM::format);

    private static MovementSummary summary(Instant end, int sdMg) {
        return new MovementSummary(end, Duration.ofSeconds(2), new Acceleration(10, -990, 60), sdMg, 1000 + sdMg);
    }

    private Optional<Wearers.Notice> anna(Instant at, int sdMg) {
        return wearers.summary("node-anna", "Anna", summary(at, sdMg));
    }

    private Optional<Wearers.Notice> bert(Instant at, int sdMg) {
        return wearers.summary("node-bert", "Bert", summary(at, sdMg));
    }

    @Test
    void movementIsASpreadAboveTheThreshold() {
        assertFalse(wearers.moving(summary(T0, 30)), "30 mg: the node's own still limit");
        assertTrue(wearers.moving(summary(T0, 31)));
    }

    @Test
    void roomActivityWhileAnotherWearerMovesIsThatWearers() {
        anna(T0, 4);
        bert(T0, 4);
        bert(T0.plusSeconds(10), 200);
        Wearers.Attribution a = wearers.room(T0.plusSeconds(12), "r-k", "Kitchen");
        assertEquals(Set.of("node-bert"), a.countsFor(), "Bert's node moved 2 s before: Bert explains it");
        assertEquals(Set.of("node-bert"), a.seenThere());
        Wearers.View annaView = wearers.view("node-anna").orElseThrow();
        assertEquals(1, annaView.explained());
        assertEquals(Set.of("Bert"), annaView.explainedBy());
        assertEquals("", annaView.roomName(), "Anna was not seen in the kitchen");
        assertEquals("Kitchen", wearers.view("node-bert").orElseThrow().roomName());
    }

    @Test
    void withNobodyElseMovingRoomActivityMayBeTheWearerAndCounts() {
        anna(T0, 4);
        bert(T0, 4);
        bert(T0.plusSeconds(10), 200);
        Wearers.Attribution a = wearers.room(T0.plusSeconds(16), "r-k", "Kitchen");
        assertEquals(Set.of("node-anna", "node-bert"), a.countsFor(), "Bert's movement is 6 s old: not moving now");
        anna(T0.plusSeconds(20), 150);
        Wearers.Attribution own = wearers.room(T0.plusSeconds(21), "r-b", "Bathroom");
        assertEquals(Set.of("node-anna"), own.countsFor(), "Anna's own movement: hers only");
        assertEquals("Bathroom", wearers.view("node-anna").orElseThrow().roomName());
    }

    @Test
    void twoWearersMovingExplainEachOther() {
        anna(T0, 150);
        bert(T0, 150);
        assertEquals(Set.of(), wearers.room(T0.plusSeconds(1), "r-k", "Kitchen").countsFor(),
                "either may have been seen: each one's own movement counts, the room activity for neither");
    }

    @Test
    void aNodeStillForTwoHoursWhileTheSensorsSeeSomeoneSeemsNotWornUntilItMoves() {
        anna(T0.plusSeconds(12 * 60), 120); // 10:12: last movement
        anna(T0.plusSeconds(12 * 60 + 2), 3);
        Instant almost = T0.plusSeconds(12 * 60).plus(Duration.ofHours(2)).minusSeconds(1);
        assertEquals(List.of(), wearers.room(almost, "r-k", "Kitchen").notices());
        Wearers.Attribution a = wearers.room(almost.plusSeconds(1), "r-k", "Kitchen");
        assertEquals(List.of(new Wearers.Notice("node-anna", "Anna's pendant seems not to be worn: it has not moved "
                + "since 10:12 while the sensors saw someone in the Kitchen; until it moves again, Anna is watched "
                + "by the room sensors")), a.notices());
        assertEquals(Set.of("node-anna"), a.countsFor());
        assertFalse(wearers.view("node-anna").orElseThrow().worn());
        assertEquals(List.of(), wearers.room(almost.plusSeconds(60), "r-k", "Kitchen").notices(), "said once");

        Instant moved = almost.plusSeconds(600);
        assertEquals(Optional.of(new Wearers.Notice("node-anna", "Anna's pendant is worn again: it moved at 12:21; "
                + "its movement counts as Anna's activity again")), anna(moved, 90));
        assertTrue(wearers.view("node-anna").orElseThrow().worn());
        assertEquals(Optional.empty(), anna(moved.plusSeconds(2), 90), "said once");
    }

    @Test
    void aNodeNeverMovedCountsFromWhenItWasFirstHeard() {
        anna(T0, 3);
        assertEquals(List.of(), wearers.room(T0.plus(Duration.ofMinutes(119)), "r-k", "Kitchen").notices());
        assertEquals(1, wearers.room(T0.plus(Duration.ofMinutes(120)), "r-k", "Kitchen").notices().size());
    }

    @Test
    void noNotWornNoticeWhileAnotherWearerExplainsTheRoomActivity() {
        anna(T0, 3);
        for (int m = 0; m <= 180; m += 10) {
            Instant at = T0.plus(Duration.ofMinutes(m));
            bert(at, 200);
            Wearers.Attribution a = wearers.room(at.plusSeconds(1), "r-k", "Kitchen");
            assertEquals(List.of(), a.notices(), "at +" + m + " min Bert explains it");
            assertEquals(Set.of("node-bert"), a.countsFor());
        }
        assertTrue(wearers.view("node-anna").orElseThrow().worn());
        assertEquals(19, wearers.view("node-anna").orElseThrow().explained());
    }

    @Test
    void aWearerWhoseNodeIsNotWornIsWatchedByEveryRoomActivity() {
        anna(T0, 3);
        bert(T0, 3);
        assertEquals(2, wearers.room(T0.plus(Duration.ofHours(2)), "r-k", "Kitchen").notices().size(),
                "Anna's and Bert's nodes both lay still: notices for both");
        Instant at = T0.plus(Duration.ofHours(3));
        bert(at, 200); // Bert's node moves again: worn again
        Wearers.Attribution a = wearers.room(at.plusSeconds(1), "r-h", "Hall");
        assertEquals(Set.of("node-anna", "node-bert"), a.countsFor(),
                "Anna's pendant is not worn: she falls back to the room sensors, as without a node");
        assertEquals("Kitchen", wearers.view("node-anna").orElseThrow().roomName(),
                "but it may have been Bert: not where Anna was last seen");
    }

    @Test
    void badSettingsAreRefusedInWords() {
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> new WearerSettings(30, Duration.ZERO, Duration.ofHours(2)));
        assertTrue(e.getMessage().contains("must be positive"), e.getMessage());
    }
}
