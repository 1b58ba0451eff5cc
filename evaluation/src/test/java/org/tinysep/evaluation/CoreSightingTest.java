package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.simulator.replay.Kind;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * Issue 28, session 33: the core replay tells a bed or seat mat by the node's type, as the platform does. By the
 * name ("starts with Bed"), Ordonez B's bedroom movement sensor "Bedroom door (PIR)" was a bed mat turning ON: every
 * bedroom movement began sleep in the core, by day too, and the core's bedroom limits were not the platform's.
 */
class CoreSightingTest {

    private static final Instant T = Instant.parse("2012-11-30T09:19:25Z");

    private static List<Boolean> states(String what, AmicaNodeType type) {
        Sighting s = new CoreReplay.Act(T, "Bedroom", what, false, false, type).sighting();
        return List.of(s.inBed(), s.seated(), s.upFromBed());
    }

    @Test
    void aBedroomMovementSensorIsNoBed() {
        assertEquals(List.of(false, false, false), states("Bedroom door (PIR) on", AmicaNodeType.MOVEMENT),
                "in bed, sat down, got up");
        assertEquals(List.of(false, false, false), states("Seating area (PIR) on", AmicaNodeType.MOVEMENT));
    }

    @Test
    void theMatsAreToldByTheirType() {
        assertEquals(List.of(true, false, false), states("Bed (Pressure) on", AmicaNodeType.PRESENCE_BED));
        assertEquals(List.of(false, false, true), states("Bed (Pressure) off", AmicaNodeType.PRESENCE_BED));
        assertEquals(List.of(false, true, false), states("Sofa (Pressure) on", AmicaNodeType.PRESENCE_SEAT));
        assertEquals(List.of(true, false, false), states("Mattress on", AmicaNodeType.PRESENCE_BED),
                "a bed mat whose name does not start with Bed");
    }

    /**
     * A mat recorded ON twice without an OFF between (Ordonez B, 30 November: seat ON 12:41:45 and again 12:56:27)
     * is one change: the platform's device tells changes only, so the quiet period after the living-room movement at
     * 12:55:16 is not a sit for the platform and must not be one for the core. A sensor's first report in the
     * recording is its resting state (B's first event, seat ON at 21:14:21, was learned as a 3 h 07 evening sit).
     */
    @Test
    void aMatRecordedInTheStateItHadIsNoActivity() {
        NodeSpec seat = new NodeSpec("Seat", NodeSpec.AMICA, AmicaAddress.parse("1.41"), AmicaNodeType.PRESENCE_SEAT,
                "Living Room", "", "Seat (Pressure)");
        NodeSpec pir = new NodeSpec("Door Living", NodeSpec.AMICA, AmicaAddress.parse("1.40"), AmicaNodeType.MOVEMENT,
                "Living Room", "", "Living door (PIR)");
        LocalDateTime t = LocalDateTime.parse("2012-11-30T12:41:45");
        List<SensorEvent> events = List.of(
                new SensorEvent(t.minusHours(3), "Seat", "Living", Kind.PRESSURE, false),
                new SensorEvent(t, "Seat", "Living", Kind.PRESSURE, true),
                new SensorEvent(t.plusMinutes(13), "Door Living", "Living", Kind.MOTION, true),
                new SensorEvent(t.plusMinutes(13).plusSeconds(3), "Door Living", "Living", Kind.MOTION, true),
                new SensorEvent(t.plusMinutes(14).plusSeconds(42), "Seat", "Living", Kind.PRESSURE, true));
        CoreReplay core = new CoreReplay(new Home("test", events, List.of(), null, null, List.of(seat, pir)), true);
        assertEquals(List.of("Seat (Pressure) on", "Living door (PIR) on", "Living door (PIR) on"),
                core.acts(events.subList(1, events.size())).stream().map(CoreReplay.Act::what).toList(),
                "a stretch starts from the recording's state (seat OFF): its ON counts");
        assertEquals(List.of("Seat (Pressure) on", "Living door (PIR) on", "Living door (PIR) on"),
                core.acts(events).stream().map(CoreReplay.Act::what).toList(),
                "the seat's first report (OFF) is its state; a movement sensor's every report counts; the seat's "
                        + "second ON is no change");
    }
}
