package org.tinysep.flatoccupancy.internal;

import static org.tinysep.flatoccupancy.internal.Fixtures.door;
import static org.tinysep.flatoccupancy.internal.Fixtures.flat;
import static org.tinysep.flatoccupancy.internal.Fixtures.movement;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.logs.RecordingLogs;

/** Door reports through the device: a door node's first report is its resting state, not a closing. */
class FlatOccupancyDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final FlatOccupancyDevice flat = flat(logs, T0);

    @Test
    void aFirstClosedReportStartsNoLeaveCheckButARealClosingDoes() {
        DoorProvider front = door("front");
        flat.movementReported(movement(), new MovementEvent(true, T0));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy());

        flat.doorChanged(front, OpenState.CLOSED, true, T0.plusSeconds(5)); // the node powers up: closed
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy(), "a first report is no evidence of leaving");

        flat.doorChanged(front, OpenState.OPEN, T0.plusSeconds(700));
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(705));
        flat.tick(T0.plusSeconds(705 + 600));
        assertEquals(Occupancy.UNOCCUPIED, flat.occupancy(), "an observed closing still starts the leave check");
    }

    @Test
    void aFirstOpenReportCountsAsAnArrival() {
        flat.doorChanged(door("front"), OpenState.OPEN, true, T0);
        assertEquals(Occupancy.OCCUPIED, flat.occupancy());
    }

    /** Issue 25, item 1: Flat Occupancy watches the person: it says which rooms it can no longer see. */
    @Test
    void itWatchesThePersonAndListsTheRoomsItCannotSee() {
        assertEquals("", flat.parameters().stream().filter(p -> p.key().equals("roomsNotSeen")).findFirst()
                .orElseThrow(() -> new AssertionError("no roomsNotSeen parameter")).value());
    }

    /** Issue 29, idle: the ticker calls the device only while a leave check runs, and a closing door says when. */
    @Test
    void itNeedsATickOnlyWhileALeaveCheckRuns() {
        List<Instant> asked = new ArrayList<>();
        flat.whenDue(asked::add);
        DoorProvider front = door("front");
        flat.movementReported(movement(), new MovementEvent(true, T0));
        assertEquals(null, flat.tick(T0.plusSeconds(1)), "occupied, no leave check: no tick needed");

        flat.doorChanged(front, OpenState.OPEN, T0.plusSeconds(10));
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(15));
        Instant end = T0.plusSeconds(15 + 600);
        assertEquals(List.of(end), asked.stream().filter(Objects::nonNull).distinct().toList(),
                "the closing door asks for a tick when its leave check ends");
        assertEquals(end, flat.tick(T0.plusSeconds(16)), "still checking");
        assertEquals(null, flat.tick(end), "the check ended: no tick needed");
        assertEquals(Occupancy.UNOCCUPIED, flat.occupancy());
    }
}
