package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;

/** The mapping file format, defaults by kind and the address allocator, through {@link ReplayPlan}. */
class SensorMappingTest {

    private static final LocalDateTime T = LocalDateTime.parse("2020-01-01T07:00");

    @Test
    void builtInDefaultsByKind() {
        ReplayPlan plan = ReplayPlan.of(List.of(
                ev(0, "pir", Kind.MOTION, true), ev(1, "d1", Kind.DOOR, true), ev(2, "mat", Kind.PRESSURE, true),
                ev(3, "flush", Kind.FLUSH, true), ev(4, "tv", Kind.ELECTRIC, true), ev(5, "x", Kind.OTHER, true)),
                SensorMapping.defaults());
        List<NodeSpec> n = plan.nodes();
        assertEquals(List.of(AmicaNodeType.MOVEMENT, AmicaNodeType.WINDOW, AmicaNodeType.PRESENCE_SEAT,
                AmicaNodeType.PRESENCE_FLUSH, AmicaNodeType.PRESENCE_APPLIANCE, AmicaNodeType.WINDOW),
                n.stream().map(NodeSpec::type).toList(), "a door contact that does not lead outside is a window node");
        assertEquals("", n.get(1).doorKind());
        assertEquals("", n.get(0).doorKind());
        assertEquals(List.of("1.100", "1.101", "1.102", "1.103", "1.104", "1.105"),
                n.stream().map(s -> s.address().toString()).toList());
        assertEquals("Room", n.get(0).room());
        assertEquals("pir", n.get(0).name());
    }

    @Test
    void builtInDefaultsReadNamesAndRoomsForOuterDoorsAndBeds() throws Exception {
        ReplayPlan plan = ReplayPlan.of(List.of(ev(0, "Frontdoor", Kind.DOOR, true),
                ev(1, "Main door", Kind.DOOR, true), ev(2, "Fridge", Kind.DOOR, true),
                ev(3, "Bathroom door", Kind.DOOR, true), ev(4, "Bed", Kind.PRESSURE, true),
                ev(5, "Sofa", Kind.PRESSURE, true), ev(6, "Armchair", Kind.PRESSURE, true)), SensorMapping.defaults());
        List<NodeSpec> n = plan.nodes();
        assertEquals(List.of("OUTER", "OUTER", "", ""), n.subList(0, 4).stream().map(NodeSpec::doorKind).toList(),
                "a door whose name says it leads outside is the outer door; furniture and rooms are not");
        assertEquals(List.of(AmicaNodeType.DOOR, AmicaNodeType.DOOR, AmicaNodeType.WINDOW, AmicaNodeType.WINDOW),
                n.subList(0, 4).stream().map(NodeSpec::type).toList());
        assertEquals(List.of(AmicaNodeType.PRESENCE_BED, AmicaNodeType.PRESENCE_SEAT, AmicaNodeType.PRESENCE_SEAT),
                n.subList(4, 7).stream().map(NodeSpec::type).toList());
        ReplayPlan byRoom = ReplayPlan.of(List.of(new SensorEvent(T, "D001", "Entry", Kind.DOOR, true),
                new SensorEvent(T, "M017", "Bedroom", Kind.PRESSURE, true),
                new SensorEvent(T, "Chair", "Bedroom", Kind.PRESSURE, true)), SensorMapping.defaults());
        assertEquals("OUTER", byRoom.nodes().get(0).doorKind(), "a door in the entrance room");
        assertEquals(List.of(AmicaNodeType.PRESENCE_BED, AmicaNodeType.PRESENCE_SEAT),
                byRoom.nodes().subList(1, 3).stream().map(NodeSpec::type).toList(), "a mat in the bedroom, a chair");
        SensorMapping file = SensorMapping.parse(List.of("default = door; type = door; doorKind = INNER",
                "sensor = Bed; type = presence-seat"), "m.mapping");
        ReplayPlan told = ReplayPlan.of(List.of(ev(0, "Frontdoor", Kind.DOOR, true), ev(1, "Bed", Kind.PRESSURE,
                true)), file);
        assertEquals(new NodeSpec("Frontdoor", "amica", new AmicaAddress(1, 100), AmicaNodeType.DOOR, "Room", "INNER",
                "Frontdoor"), told.nodes().get(0), "a default line decides, even one that reads like the built-in");
        assertEquals(AmicaNodeType.PRESENCE_SEAT, told.nodes().get(1).type(), "a sensor line decides");
        SensorMapping allInner = SensorMapping.parse(List.of("default = door; type = window"), "m.mapping");
        assertEquals(AmicaNodeType.WINDOW, ReplayPlan.of(List.of(ev(0, "Frontdoor", Kind.DOOR, true)), allInner)
                .nodes().get(0).type(), "a changed default line decides");
    }

    @Test
    void fileEntriesOverrideDefaultsAndAllocatorSkipsUsedAddresses() throws Exception {
        SensorMapping m = SensorMapping.parse(List.of(
                "# comment", "", "allocate = 2.7",
                "default = pressure; type = movement",
                "Sensor = Maindoor; node = amica 2.8; type = door; doorKind = outer; room = Hall; name = Front door",
                "sensor = Fridge; type = window",
                "sensor = Bed; room = Bedroom"), "m.mapping");
        ReplayPlan plan = ReplayPlan.of(List.of(ev(0, "Fridge", Kind.DOOR, true), ev(1, "Maindoor", Kind.DOOR, true),
                ev(2, "Bed", Kind.PRESSURE, true), ev(3, "Other", Kind.DOOR, true)), m);
        List<NodeSpec> n = plan.nodes();
        assertEquals(new NodeSpec("Fridge", "amica", new AmicaAddress(2, 7), AmicaNodeType.WINDOW, "Room", "", "Fridge"),
                n.get(0));
        assertEquals(new NodeSpec("Maindoor", "amica", new AmicaAddress(2, 8), AmicaNodeType.DOOR, "Hall", "OUTER",
                "Front door"), n.get(1));
        assertEquals(new NodeSpec("Bed", "amica", new AmicaAddress(2, 9), AmicaNodeType.MOVEMENT, "Bedroom", "", "Bed"),
                n.get(2));
        assertEquals(AmicaNodeType.WINDOW, n.get(3).type(), "a door contact the file does not describe");
        assertEquals(new AmicaAddress(2, 10), n.get(3).address());
        assertTrue(m.isMapped("Bed"));
        assertEquals(List.of("Maindoor", "Fridge", "Bed"), m.mappedSensors());
    }

    @Test
    void malformedLinesNameFileAndLine() {
        assertError("m:2: sensor 'a' is mapped twice", "sensor = a", "sensor = a");
        assertError("m:2: address 1.5 of 'b' is already used by 'a'", "sensor = a; node = amica 1.5",
                "sensor = b; node = amica 1.5");
        assertError("m:1: unknown key 'colour'", "sensor = a; colour = red");
        assertError("m:1: type 'heater': expected movement, pet-collar, door, window, presence-bed",
                "sensor = a; type = heater");
        assertError("m:1: doorKind 'OUTER': only for 'type = door'", "sensor = a; type = window; doorKind = OUTER");
        assertError("m:1: node 'sunspot 0014.4F01'", "sensor = a; node = sunspot 0014.4F01");
        assertError("m:1: address 1.0 is the platform's", "sensor = a; node = amica 1.0");
        assertError("m:1: AmICA address '1.300'", "allocate = 1.300");
        assertError("m:1: expected a 'sensor = ...'", "hello = world");
        assertError("m:1: 'nonsense' is not 'key = value'", "sensor = a; nonsense");
        assertError("m:1: unknown sensor kind 'smoke'", "default = smoke; type = window");
        assertError("m:1: a default line needs 'type = ...'", "default = flush");
    }

    @Test
    void allocatorReportsAFullNetgroup() throws Exception {
        SensorMapping m = SensorMapping.parse(List.of("allocate = 1.254"), "m");
        List<SensorEvent> events = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            events.add(ev(i, "s" + i, Kind.MOTION, true));
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ReplayPlan.of(events, m));
        assertTrue(e.getMessage().startsWith("no free address left in netgroup 1"), e.getMessage());
    }

    static SensorEvent ev(int seconds, String sensor, Kind kind, boolean on) {
        return new SensorEvent(T.plusSeconds(seconds), sensor, "Room", kind, on);
    }

    private static void assertError(String prefix, String... lines) {
        ReplayFormatException e = assertThrows(ReplayFormatException.class,
                () -> SensorMapping.parse(List.of(lines), "m"));
        assertTrue(e.getMessage().startsWith(prefix), e.getMessage());
    }
}
