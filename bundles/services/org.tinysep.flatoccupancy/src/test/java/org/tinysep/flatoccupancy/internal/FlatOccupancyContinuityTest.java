package org.tinysep.flatoccupancy.internal;

import static org.tinysep.flatoccupancy.internal.Fixtures.door;
import static org.tinysep.flatoccupancy.internal.Fixtures.movement;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 10 items 1 and 2 for Flat Occupancy: a restart resumes the saved decision (not UNKNOWN), a leave check
 * pending at the crash still ends; a clock that went back (or a backup from the future) is counted from now.
 */
class FlatOccupancyContinuityTest {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");
    private static final Instant FUTURE = Instant.parse("2099-01-01T00:00:00Z");

    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final DoorProvider front = door("front");

    private FlatOccupancyDevice device(ComponentBackup saved) {
        FlatOccupancyDevice d = new FlatOccupancyDevice(
                new DriverContext(null, "d", "FlatOccupancy", logs.reporter(), new PlatformClock(() -> now)),
                Duration.ofMinutes(10), Duration.ofSeconds(10));
        if (saved != null) {
            restore(d, saved);
        }
        return d;
    }

    /** What {@code AbstractDriver.addDevice} does with a device's backup before it registers. */
    private static void restore(FlatOccupancyDevice d, ComponentBackup saved) {
        try {
            Method m = AbstractDevice.class.getDeclaredMethod("restore", ComponentBackup.class);
            m.setAccessible(true);
            m.invoke(d, saved);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }

    private void motion(FlatOccupancyDevice d) {
        d.movementReported(movement(), new MovementEvent(true, now));
    }

    @Test
    void aRestartResumesTheSavedOccupancyWithItsSince() {
        FlatOccupancyDevice before = device(null);
        motion(before);
        now = T0.plusSeconds(3600);
        ComponentBackup saved = before.backup();

        now = T0.plusSeconds(7200); // killed, restarted an hour later
        FlatOccupancyDevice after = device(saved);
        assertEquals(Occupancy.OCCUPIED, after.occupancy(), "not UNKNOWN: the person is still home");
        assertEquals(T0, after.since());
        assertTrue(logs.events().stream().anyMatch(e -> e.message().startsWith("restored after a restart: flat "
                + "occupied since " + T0)), logs.events().toString());
    }

    @Test
    void aLeaveCheckPendingAtTheCrashEndsAtItsDeadline() {
        FlatOccupancyDevice before = device(null);
        motion(before);
        now = T0.plusSeconds(100);
        before.doorChanged(front, OpenState.OPEN, now);
        now = T0.plusSeconds(105);
        before.doorChanged(front, OpenState.CLOSED, now);
        ComponentBackup saved = before.backup();

        now = T0.plusSeconds(3000);
        FlatOccupancyDevice after = device(saved);
        after.tick(now);
        assertEquals(Occupancy.UNOCCUPIED, after.occupancy());
        assertEquals(T0.plusSeconds(105 + 600), after.since(), "stamped with the leave check's deadline");
    }

    @Test
    void timeJumpForwardsThenBackRebasesTheLeaveCheckOnTheNewClock() {
        FlatOccupancyDevice d = device(null);
        motion(d);
        now = FUTURE; // a synchronised day ahead: the person leaves
        d.doorChanged(front, OpenState.OPEN, now);
        d.doorChanged(front, OpenState.CLOSED, now);
        now = T0.plusSeconds(60); // back to real time
        d.tick(now);
        assertTrue(logs.events().stream().anyMatch(e -> e.message().startsWith("clock went back from " + FUTURE
                + " to " + now)), logs.events().toString());
        now = now.plusSeconds(600);
        d.tick(now);
        assertEquals(Occupancy.UNOCCUPIED, d.occupancy(), "the leave check ran its 10 min on the new clock");
        assertEquals(now, d.since());

        now = now.plusSeconds(5);
        motion(d);
        assertEquals(Occupancy.OCCUPIED, d.occupancy());
    }

    @Test
    void aBackupFromTheFutureIsCountedFromNow() {
        now = FUTURE;
        FlatOccupancyDevice before = device(null);
        motion(before);
        ComponentBackup saved = before.backup();
        now = T0;
        FlatOccupancyDevice after = device(saved);
        assertEquals(Occupancy.OCCUPIED, after.occupancy());
        assertEquals(T0, after.since(), "not 2099");
    }

    @Test
    void anUnreadableSavedStateStartsUnknownWithAProblem() {
        FlatOccupancyDevice d = device(new ComponentBackup("u", org.tinysep.api.backup.ComponentKind.DEVICE, "d",
                "FlatOccupancy", "FlatOccupancy", "Flat occupancy", Map.of(), "", null, null,
                Map.of("occupancy", "MAYBE", "since", "x"), T0));
        assertEquals(Occupancy.UNKNOWN, d.occupancy());
        assertTrue(logs.events().stream().anyMatch(e -> e.message().startsWith("saved occupancy")),
                logs.events().toString());
    }
}
