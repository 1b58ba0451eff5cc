package org.tinysep.flatoccupancy.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.flatoccupancy.internal.Fixtures.door;
import static org.tinysep.flatoccupancy.internal.Fixtures.movement;

import java.time.Duration;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.AllocationMeter;
import org.tinysep.device.support.time.PlatformClock;

/**
 * What one movement report costs Flat Occupancy on the radio's delivery thread, in bytes allocated per report: an
 * occupied flat whose front door closed long ago (so the exit grace and the clock check have times to compare),
 * the hall sensor reporting. The decision does not change, so nothing needs building: no event's words, no
 * closure, no time sums.
 */
class MovementReportCostTest {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final FlatOccupancyDevice flat = new FlatOccupancyDevice(
            new DriverContext(null, "d", "FlatOccupancy", logs.reporter(), new PlatformClock(() -> now)),
            Duration.ofMinutes(10), Duration.ofSeconds(10));
    private final MovementProvider hall = movement();
    private final DoorProvider front = door("front");

    @Test
    void aMovementReportThatChangesNothingAllocatesNothing() {
        flat.doorChanged(front, OpenState.OPEN, T0);
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(5)); // a leave check, cancelled by the motion
        now = T0.plusSeconds(60);
        MovementEvent report = new MovementEvent(true, now);
        flat.movementReported(hall, report);
        int events = logs.events().size();

        double bytes = AllocationMeter.bytesPerCall(50_000, () -> flat.movementReported(hall, report));

        assertTrue(bytes < 8, "bytes allocated per movement report: " + bytes);
        assertEquals(Occupancy.OCCUPIED, flat.occupancy());
        assertEquals(events, logs.events().size(), "no event for a report that changes nothing");
    }

    /** The words of the event stay as they were, though they are built only when the decision changes. */
    @Test
    void theEventStillNamesTheSensor() {
        flat.movementReported(hall, new MovementEvent(true, T0));
        assertTrue(logs.events().stream()
                .anyMatch(e -> e.message().equals("flat occupied (motion from hall-movement)")), logs.events().toString());
    }
}
