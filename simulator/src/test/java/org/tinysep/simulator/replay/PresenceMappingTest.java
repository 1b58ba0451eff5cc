package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.LocalDateTime;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.ReedSwitchStatus;

/** Issue 11: recorded mats, flushes and appliances replay as presence nodes; window nodes stay valid. */
class PresenceMappingTest {

    private static final LocalDateTime T = LocalDateTime.parse("2020-01-01T07:00");

    private static SensorEvent ev(int s, String sensor, Kind kind, boolean on) {
        return new SensorEvent(T.plusSeconds(s), sensor, "Room", kind, on);
    }

    @Test
    void presenceTypesAreMappableAndWindowStillIs() throws Exception {
        SensorMapping m = SensorMapping.parse(List.of("sensor = Bed; type = presence-bed",
                "sensor = Sofa; type = window", "default = electric; type = presence-appliance"), "m");
        ReplayPlan plan = ReplayPlan.of(List.of(ev(0, "Bed", Kind.PRESSURE, true), ev(1, "Sofa", Kind.PRESSURE, true),
                ev(2, "Kettle", Kind.ELECTRIC, true), ev(3, "Bed", Kind.PRESSURE, false)), m);
        assertEquals(List.of(AmicaNodeType.PRESENCE_BED, AmicaNodeType.WINDOW, AmicaNodeType.PRESENCE_APPLIANCE),
                plan.nodes().stream().map(NodeSpec::type).toList());
        assertEquals(List.of(Signal.CONTACT_OPEN, Signal.CONTACT_OPEN, Signal.CONTACT_OPEN, Signal.CONTACT_CLOSED),
                plan.actions().stream().map(NodeAction::signal).toList());
        assertEquals(new ReedSwitchStatus(true), plan.actions().get(0).signal().payload(), "ON = A 1");
        assertEquals(false, plan.nodes().get(0).isMotion());
        ReplayFormatException e = assertThrows(ReplayFormatException.class,
                () -> SensorMapping.parse(List.of("sensor = a; type = presence-sofa"), "m"));
        assertEquals("m:1: type 'presence-sofa': expected movement, pet-collar, door, window, presence-bed, "
                + "presence-seat, presence-flush or presence-appliance", e.getMessage());
        assertThrows(ReplayFormatException.class, () -> SensorMapping.parse(List.of(
                "sensor = a; type = presence-seat; doorKind = OUTER"), "m"));
    }

    @Test
    void theBuiltInDefaultsReplayMatsFlushesAndAppliancesAsPresenceNodes() {
        ReplayPlan plan = ReplayPlan.of(List.of(ev(0, "mat", Kind.PRESSURE, true), ev(1, "wc", Kind.FLUSH, true),
                ev(2, "tv", Kind.ELECTRIC, true), ev(3, "x", Kind.OTHER, true)), SensorMapping.defaults());
        assertEquals(List.of(AmicaNodeType.PRESENCE_SEAT, AmicaNodeType.PRESENCE_FLUSH,
                AmicaNodeType.PRESENCE_APPLIANCE, AmicaNodeType.WINDOW),
                plan.nodes().stream().map(NodeSpec::type).toList());
    }

    @Test
    void theOrdonezMappingsUsePresenceNodesByRecordedName() throws Exception {
        Map<String, AmicaNodeType> byName = Map.of("Seat", AmicaNodeType.PRESENCE_SEAT, "Bed",
                AmicaNodeType.PRESENCE_BED, "Toilet", AmicaNodeType.PRESENCE_FLUSH, "Microwave",
                AmicaNodeType.PRESENCE_APPLIANCE, "Toaster", AmicaNodeType.PRESENCE_APPLIANCE, "Fridge",
                AmicaNodeType.WINDOW, "Cupboard", AmicaNodeType.WINDOW, "Cabinet", AmicaNodeType.WINDOW);
        for (String home : List.of("ordonez-a.mapping", "ordonez-b.mapping")) {
            Map<String, AmicaNodeType> types = types(home);
            byName.forEach((sensor, type) -> {
                if (types.containsKey(sensor)) { // Home B has no Toaster and no Cabinet
                    assertEquals(type, types.get(sensor), home + ": " + sensor);
                }
            });
            assertEquals(AmicaNodeType.PRESENCE_SEAT, types.get("Seat"), home);
        }
    }

    private static Map<String, AmicaNodeType> types(String resource) throws Exception {
        SensorMapping m = SensorMapping.fromResource(resource);
        List<SensorEvent> events = m.mappedSensors().stream().map(s -> ev(0, s, Kind.OTHER, true)).toList();
        return ReplayPlan.of(events, m).nodes().stream().collect(Collectors.toMap(NodeSpec::sensor, NodeSpec::type));
    }
}
