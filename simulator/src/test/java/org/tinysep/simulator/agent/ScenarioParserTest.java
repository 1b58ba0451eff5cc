package org.tinysep.simulator.agent;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.tinysep.simulator.flat.FlatLoader;
import org.tinysep.simulator.flat.House;

class ScenarioParserTest {

    private static ScenarioParser parser() throws Exception {
        House house = FlatLoader.load("flat-a").house();
        return new ScenarioParser(house::roomName, Set.of("hall-motion"));
    }

    @Test
    void everyFormParses() throws Exception {
        Scenario s = parser().parse("""
                # a comment
                07:10 anna bedroom -> bathroom
                7:30:15 Anna kitchen       # trailing comment
                08:30 anna leaves
                12:00 anna arrives
                12:01 anna arrives in living room
                14:02 anna collapses in bathroom
                14:30 anna gets up
                22:00 anna sleeps
                06:00 anna wakes
                09:00 rex (pet) living room
                10:00 battery hall-motion off
                """, "s.txt");
        List<Step> st = s.steps();
        assertEquals(11, st.size());
        assertEquals(Set.of("rex"), s.pets());
        assertEquals(List.of("anna", "rex"), s.agents());
        Step first = st.get(0);
        assertEquals(6 * 3600, first.secondOfDay());
        assertEquals(Action.WAKES, first.action());
        Step fromTo = st.get(1);
        assertEquals(Action.FROM_TO, fromTo.action());
        assertEquals("Bedroom", fromTo.room());
        assertEquals("Bathroom", fromTo.room2());
        assertEquals(7 * 3600 + 30 * 60 + 15, st.get(2).secondOfDay());
        assertEquals("Kitchen", st.get(2).room());
        assertEquals(Action.ARRIVES, st.get(6).action());
        assertNull(st.get(6).room());
        assertEquals("Living Room", st.get(7).room());
        assertEquals(Action.BATTERY, st.get(5).action());
        assertEquals("hall-motion", st.get(5).target());
        assertEquals(Action.COLLAPSES, st.get(8).action());
        assertEquals("Bathroom", st.get(8).room());
        assertEquals(Action.WAKES, st.get(9).action());
        assertEquals(Action.SLEEPS, st.get(10).action());
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "25:00 anna kitchen; bad time 25:00",
            "07:61 anna kitchen; bad time",
            "0710 anna kitchen; expected 'HH:MM[:SS] <name>",
            "07:10 anna attic; unknown room 'attic'",
            "07:10 anna kitchen -> attic; unknown room 'attic'",
            "07:10 anna; nothing happens to anna",
            "07:10 anna leaves kitchen; 'leaves' takes no room",
            "07:10 anna collapses bathroom; expected 'collapses in <room>'",
            "07:10 battery hall-motion maybe; expected 'battery <node id> on|off'",
            "07:10 battery toaster off; unknown node 'toaster'"})
    void badLinesNameFileLineAndText(String line, String expected) throws Exception {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> parser().parse("07:00 anna kitchen\n\n" + line + "\n", "day.txt"));
        assertTrue(e.getMessage().startsWith("day.txt:3: ") && e.getMessage().contains(expected)
                && e.getMessage().contains(line.trim()), e.getMessage());
    }

    @Test
    void theDemoDayParses() throws Exception {
        Scenario s = org.tinysep.simulator.cli.Simulation.scenario("demo-day", FlatLoader.load("flat-a"));
        assertEquals(List.of("anna", "rex", "ben"), s.agents());
        assertTrue(s.steps().stream().anyMatch(x -> x.action() == Action.COLLAPSES && "Bathroom".equals(x.room())));
    }
}
