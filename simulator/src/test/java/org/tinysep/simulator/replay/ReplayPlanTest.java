package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.simulator.replay.SensorMappingTest.ev;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;

/** Events + mapping → time-ordered node actions. */
class ReplayPlanTest {

    @Test
    void actionsFollowEventTimeAndNodeType() throws Exception {
        SensorMapping m = SensorMapping.parse(List.of("sensor = seat; type = movement"), "m");
        ReplayPlan plan = ReplayPlan.of(List.of(ev(5, "pir", Kind.MOTION, false), ev(1, "pir", Kind.MOTION, true),
                ev(2, "door", Kind.DOOR, true), ev(3, "door", Kind.DOOR, false), ev(4, "seat", Kind.PRESSURE, true),
                ev(4, "bed", Kind.PRESSURE, true)), m);
        assertEquals(List.of(Signal.MOTION_ON, Signal.CONTACT_OPEN, Signal.CONTACT_CLOSED, Signal.MOTION_ON,
                Signal.CONTACT_OPEN, Signal.MOTION_OFF), plan.actions().stream().map(NodeAction::signal).toList());
        assertEquals(List.of("pir", "door", "door", "seat", "bed", "pir"),
                plan.actions().stream().map(a -> a.node().sensor()).toList());
        assertEquals(plan.actions().get(0).node(), plan.actions().get(5).node(), "one node per sensor");
        assertEquals(ev(1, "x", Kind.MOTION, true).time(), plan.start());
        assertEquals(ev(5, "x", Kind.MOTION, true).time(), plan.end());
        assertEquals(4, plan.nodes().size());
        assertEquals(java.time.Duration.ofSeconds(4), plan.offsetOf(plan.actions().get(5)));
    }

    @Test
    void signalsCarryTheAmicaPayloads() {
        assertEquals(new MotionDetection(true), Signal.MOTION_ON.payload());
        assertEquals(new MotionDetection(false), Signal.MOTION_OFF.payload());
        assertEquals(new ReedSwitchStatus(true), Signal.CONTACT_OPEN.payload());
        assertEquals(new ReedSwitchStatus(false), Signal.CONTACT_CLOSED.payload());
    }

    @Test
    void aSensorWithTwoKindsIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ReplayPlan.of(
                List.of(ev(1, "x", Kind.MOTION, true), ev(2, "x", Kind.DOOR, true)), SensorMapping.defaults()));
        assertEquals("sensor 'x' is recorded as motion and as door", e.getMessage());
    }

    @Test
    void emptyPlan() {
        ReplayPlan plan = ReplayPlan.of(List.of(), SensorMapping.defaults());
        assertEquals(List.of(), plan.actions());
        assertEquals(null, plan.start());
    }
}
