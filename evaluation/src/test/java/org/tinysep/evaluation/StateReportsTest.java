package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.replay.Kind;
import org.tinysep.simulator.replay.SensorEvent;

/** A replayed stretch starts with what real nodes would have told the restarted platform: their current state. */
class StateReportsTest {

    private static final LocalDateTime T0 = LocalDateTime.parse("2011-12-11T15:00:00");

    private static SensorEvent e(int minutes, String sensor, Kind kind, boolean on) {
        return new SensorEvent(T0.plusMinutes(minutes), sensor, "Living", kind, on);
    }

    @Test
    void eachContactAndMatReportsItsStateBeforeTheStretchAtItsFirstEvent() {
        List<SensorEvent> recording = List.of(e(0, "Seat", Kind.PRESSURE, true), e(5, "Basin", Kind.MOTION, true),
                e(10, "Door", Kind.DOOR, true), e(20, "Door", Kind.DOOR, false), e(30, "Seat", Kind.PRESSURE, false),
                e(40, "Seat", Kind.PRESSURE, true), e(50, "Bed", Kind.PRESSURE, true));
        List<SensorEvent> stretch = recording.subList(4, 7);
        List<SensorEvent> out = StateReports.prepend(recording, stretch);
        assertEquals(List.of(new SensorEvent(T0.plusMinutes(30), "Seat", "Living", Kind.PRESSURE, true),
                new SensorEvent(T0.plusMinutes(30), "Door", "Living", Kind.DOOR, false)), out.subList(0, 2),
                "the seat ON and the door CLOSED as they were; the motion sensor and the bed (no change yet) say nothing");
        assertEquals(stretch, out.subList(2, out.size()), "then the stretch unchanged");
    }

    @Test
    void aStretchFromTheRecordingsStartGetsNothing() {
        List<SensorEvent> recording = List.of(e(0, "Seat", Kind.PRESSURE, true), e(1, "Seat", Kind.PRESSURE, false));
        assertEquals(recording, StateReports.prepend(recording, recording));
    }
}
