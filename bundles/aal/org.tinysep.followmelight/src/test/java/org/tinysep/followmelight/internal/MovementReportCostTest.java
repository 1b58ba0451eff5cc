package org.tinysep.followmelight.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.AllocationMeter;
import org.tinysep.device.support.time.PlatformClock;

/**
 * What one movement report costs Follow Me Light on the radio's delivery thread when its room is lit already (most
 * reports: AmICA sensors report every 2 s while someone moves), in bytes allocated per report: the room's time is
 * renewed and nothing else is built.
 */
class MovementReportCostTest {

    private static final Instant T0 = Instant.parse("2026-11-22T19:00:00Z");
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final CountingPlacements directory = new CountingPlacements();
    private final FollowMeDevice device = new FollowMeDevice(
            new DriverContext(null, "d", "FollowMeLight", logs.reporter(), new PlatformClock(() -> T0)),
            directory, Duration.ofSeconds(30), Percent.of(70));

    @Test
    void aReportInALitRoomAllocatesNothing() {
        QuietLight lamp = new QuietLight("lamp");
        Fakes.Movement sensor = new Fakes.Movement("sensor");
        directory.place("lamp", "lounge");
        directory.place("sensor", "lounge");
        device.control(lamp);
        device.use(sensor);
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        MovementEvent report = new MovementEvent(true, T0.plusSeconds(1));
        device.movementReported(sensor, report); // lights the lounge
        int events = logs.events().size();

        double bytes = AllocationMeter.bytesPerCall(50_000, () -> device.movementReported(sensor, report));

        assertTrue(bytes < 8, "bytes allocated per movement report in a lit room: " + bytes);
        assertEquals(1, lamp.switchedOn, "switched on once");
        assertEquals(events, logs.events().size());
    }
}
