package org.tinysep.followmelight.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.Occupancy;

/** The Follow Me Light algorithm in virtual time; sensors report every 2 s while someone moves (AmICA). */
class FollowMeLogicTest {

    private static final Instant T0 = Instant.parse("2026-11-22T19:00:00Z");
    private final FollowMeLogic logic = new FollowMeLogic(Duration.ofSeconds(60));
    private final List<String> commands = new ArrayList<>();
    private int clock;

    private static Instant at(int s) {
        return T0.plusSeconds(s);
    }

    private void record(List<Command> out, int s) {
        out.forEach(c -> commands.add(c.roomUid() + (c.on() ? " on@" : " off@") + s));
    }

    /** Runs second by second to {@code until}; {@code who} says where motion is reported at a second. */
    private void run(int until, Walk... walks) {
        while (clock < until) {
            clock++;
            record(logic.tick(at(clock)), clock);
            for (Walk w : walks) {
                String room = w.roomAt(clock);
                if (room != null && clock % 2 == 0) {
                    record(w.pet ? logic.petMotion(room, at(clock)) : logic.personMotion(room, at(clock)), clock);
                }
            }
        }
    }

    /** Where one person or pet is: {@code room, fromSecond, room, fromSecond, ...}; null means gone. */
    private record Walk(boolean pet, Object... steps) {
        String roomAt(int s) {
            String room = null;
            for (int i = 0; i < steps.length; i += 2) {
                if (s >= (Integer) steps[i + 1]) {
                    room = (String) steps[i];
                }
            }
            return room;
        }
    }

    private static Walk person(Object... steps) {
        return new Walk(false, steps);
    }

    private static Walk pet(Object... steps) {
        return new Walk(true, steps);
    }

    @Test
    void aWalkFromBedroomThroughHallToKitchenSwitchesTheExpectedRoomsInOrder() {
        record(logic.occupancy(Occupancy.OCCUPIED, T0), 0);
        run(300, person("bedroom", 2, "hall", 32, "kitchen", 42));
        assertEquals(List.of("bedroom on@2", "hall on@32", "kitchen on@42", "bedroom off@90", "hall off@100"),
                commands);
        assertEquals(Set.of("kitchen"), logic.litRooms());
    }

    @Test
    void twoPersonsInTwoRoomsKeepBothLit() {
        record(logic.occupancy(Occupancy.OCCUPIED, T0), 0);
        run(1200, person("bedroom", 2), person("hall", 2, "kitchen", 10));
        assertEquals(List.of("bedroom on@2", "hall on@2", "kitchen on@10", "hall off@68"), commands);
        assertEquals(Set.of("bedroom", "kitchen"), logic.litRooms());
    }

    @Test
    void aPetAloneAtHomeDoesNothing() {
        record(logic.occupancy(Occupancy.UNOCCUPIED, T0), 0);
        run(600, pet("living", 2, "kitchen", 100));
        record(logic.occupancy(Occupancy.UNKNOWN, at(600)), 600);
        run(900, pet("living", 2));
        assertEquals(List.of(), commands);
    }

    @Test
    void aPetWithAPersonHomeMovesTheLights() {
        record(logic.occupancy(Occupancy.OCCUPIED, T0), 0);
        run(300, pet("living", 2, "kitchen", 100));
        assertEquals(List.of("living on@2", "kitchen on@100", "living off@158"), commands);
    }

    @Test
    void anEmptyFlatGoesDarkAndStaysDark() {
        record(logic.occupancy(Occupancy.OCCUPIED, T0), 0);
        run(20, person("hall", 2), person("kitchen", 2));
        record(logic.occupancy(Occupancy.UNOCCUPIED, at(20)), 20);
        run(200, person("hall", 100));
        assertEquals(List.of("hall on@2", "kitchen on@2", "hall off@20", "kitchen off@20"), commands);
        assertEquals(Set.of(), logic.litRooms());
    }

    @Test
    void motionHeardJustBeforeTheFlatBecomesOccupiedCounts() {
        record(logic.personMotion("hall", at(10)), 10);
        record(logic.personMotion("kitchen", at(1)), 1);
        record(logic.occupancy(Occupancy.OCCUPIED, at(11)), 11);
        assertEquals(List.of("hall on@11"), commands, "the kitchen motion is older than the arrival window");
    }

    @Test
    void timeJumpForwardsThenBackLetsALitRoomGoDarkOnTheNewClock() {
        Instant future = Instant.parse("2099-01-01T00:00:00Z");
        record(logic.occupancy(Occupancy.OCCUPIED, T0), 0);
        record(logic.personMotion("hall", future), 0); // a synchronised day ahead
        assertEquals(Set.of("hall"), logic.litRooms());
        record(logic.tick(at(1)), 1); // back to real time
        record(logic.tick(at(60)), 60);
        assertEquals(Set.of("hall"), logic.litRooms(), "the grace period runs from when the clock came back");
        record(logic.tick(at(61)), 61);
        assertEquals(List.of("hall on@0", "hall off@61"), commands, "not lit until 2099");

        record(logic.personMotion("hall", at(70)), 70);
        record(logic.personMotion("hall", future), 71);
        record(logic.tick(at(72)), 72); // the clock went back again
        record(logic.personMotion("hall", at(72)), 72);
        record(logic.tick(at(72 + 60)), 132);
        assertEquals(List.of("hall on@0", "hall off@61", "hall on@70", "hall off@132"), commands);
    }

    @Test
    void aDarkFlatNeedsNoTickAndALitRoomOnlyAtTheEndOfItsGracePeriod() {
        assertEquals(null, logic.nextDue(), "nothing lit: no tick needed");
        logic.occupancy(Occupancy.OCCUPIED, T0);
        logic.personMotion("hall", at(2));
        logic.personMotion("kitchen", at(10));
        assertEquals(at(62), logic.nextDue(), "the hall's grace period ends first");
        logic.personMotion("hall", at(30));
        assertEquals(at(70), logic.nextDue(), "the hall's motion restarted its grace period: the kitchen's is first");
        logic.tick(at(70));
        logic.tick(at(90));
        assertEquals(null, logic.nextDue(), "both dark again: no tick needed");
    }

    @Test
    void tickingOnlyWhenDueSwitchesTheSameAsEverySecond() {
        FollowMeLogic due = new FollowMeLogic(Duration.ofSeconds(60));
        List<String> dueCommands = new ArrayList<>();
        logic.occupancy(Occupancy.OCCUPIED, T0);
        due.occupancy(Occupancy.OCCUPIED, T0);
        Instant next = null;
        for (int s = 1; s <= 400; s++) {
            int t = s;
            record(logic.tick(at(s)), s);
            if (next != null && !at(s).isBefore(next)) {
                due.tick(at(s)).forEach(c -> dueCommands.add(c.roomUid() + (c.on() ? " on@" : " off@") + t));
                next = due.nextDue();
            }
            String room = s < 100 && s % 3 == 0 ? "hall" : s > 150 && s < 200 && s % 7 == 0 ? "bath" : null;
            if (room != null) {
                record(logic.personMotion(room, at(s)), s);
                due.personMotion(room, at(s)).forEach(c -> dueCommands.add(c.roomUid() + (c.on() ? " on@" : " off@")
                        + t));
                Instant d = due.nextDue();
                next = next == null || (d != null && d.isBefore(next)) ? d : next;
            }
        }
        assertEquals(List.of("hall on@3", "bath on@154", "hall off@159", "bath off@256"), commands);
        assertEquals(commands, dueCommands);
    }
}
