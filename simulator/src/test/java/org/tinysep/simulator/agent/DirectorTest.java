package org.tinysep.simulator.agent;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.flat.Flat;
import org.tinysep.simulator.flat.FlatLoader;

class DirectorTest {

    private static final long MIDNIGHT = 1_800_000_000L / 86400 * 86400;

    private record Run(World world, List<String> battery) {
    }

    private static Run play(String scenario, long seed, int jitter, double wander, int untilSecond) throws Exception {
        Flat flat = FlatLoader.load("flat-a");
        Scenario s = new ScenarioParser(flat.house()::roomName, flat.nodes().stream().map(n -> n.id()).collect(java.util.stream.Collectors.toSet())).parse(scenario, "t");
        World world = new World();
        List<String> battery = new ArrayList<>();
        Director d = new Director(flat.house(), "Hall", s, MIDNIGHT, seed, jitter, wander, world,
                (id, on) -> battery.add(id + " " + on));
        for (long t = MIDNIGHT; t < MIDNIGHT + untilSecond; t++) {
            d.advance(t);
        }
        return new Run(world, battery);
    }

    @Test
    void withoutRandomnessTheAgentWalksTheScriptRoomByRoom() throws Exception {
        Run r = play("""
                00:00:00 anna bedroom -> kitchen
                00:01:00 anna leaves
                00:02:00 anna arrives in bathroom
                00:03:00 anna collapses
                00:03:30 battery hall-motion off
                """, 1, 0, 0, 300);
        assertEquals(List.of("00:00:00 anna Hall", "00:00:04 anna Living Room", "00:00:08 anna Kitchen",
                "00:01:00 anna Living Room", "00:01:04 anna Hall", "00:01:04 anna leaves",
                "00:02:00 anna arrives in Hall", "00:02:04 anna Bathroom", "00:03:00 anna collapses in Bathroom",
                "00:03:30 hall-motion battery off"), r.world().trace());
        assertEquals(List.of("hall-motion false"), r.battery());
        World w = r.world();
        assertTrue(w.doorOpen("Hall", MIDNIGHT + 64));
        assertTrue(w.doorOpen("Hall", MIDNIGHT + 66));
        assertFalse(w.doorOpen("Hall", MIDNIGHT + 64 + World.DOOR_OPEN_SECONDS));
        assertTrue(w.personMotion("Bathroom", MIDNIGHT + 178, MIDNIGHT + 180));
        assertFalse(w.personMotion("Bathroom", MIDNIGHT + 181, MIDNIGHT + 299), "a collapsed person makes no motion");
    }

    @Test
    void petsMoveTheirCollarNotTheMovementSensors() throws Exception {
        Run r = play("00:00 rex (pet) kitchen\n00:01 rex living room\n", 1, 0, 0, 120);
        assertTrue(r.world().petMotion("rex", MIDNIGHT + 60, MIDNIGHT + 62));
        assertFalse(r.world().personMotion("Living Room", MIDNIGHT, MIDNIGHT + 120));
        assertFalse(r.world().petMotion("rex", MIDNIGHT + 100, MIDNIGHT + 119), "quiet 20 s after its last move");
    }

    @Test
    void theSameSeedGivesTheSameDayAndAnotherSeedAnother() throws Exception {
        String day = new String(getClass().getResourceAsStream("/scenarios/demo-day.txt").readAllBytes());
        List<String> a = play(day, 7, 90, 0.002, 86400).world().trace();
        List<String> b = play(day, 7, 90, 0.002, 86400).world().trace();
        List<String> c = play(day, 8, 90, 0.002, 86400).world().trace();
        assertEquals(a, b);
        assertNotEquals(a, c);
        for (List<String> t : List.of(a, c)) {
            assertTrue(t.stream().anyMatch(e -> e.endsWith("anna collapses in Bathroom")), t.toString());
            assertTrue(t.stream().anyMatch(e -> e.endsWith("anna leaves")));
            assertTrue(t.stream().anyMatch(e -> e.endsWith("anna arrives in Hall")));
            assertTrue(t.stream().anyMatch(e -> e.endsWith("ben leaves")));
        }
        String collapse = a.stream().filter(e -> e.endsWith("collapses in Bathroom")).findFirst().orElseThrow();
        assertTrue(collapse.compareTo("14:00:30") > 0 && collapse.compareTo("14:03:35") < 0, collapse);
    }
}
