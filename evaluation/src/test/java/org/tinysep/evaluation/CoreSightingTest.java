package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.inactivity.internal.learn.Sighting;

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
}
