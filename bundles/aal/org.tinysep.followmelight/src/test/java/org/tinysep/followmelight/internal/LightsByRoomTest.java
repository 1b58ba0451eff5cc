package org.tinysep.followmelight.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/**
 * The packet → light command path: finding a room's lights is one index read, not a look-up of every light's room
 * per switching, so it costs the same with 4 lights in the flat or 400; and the index follows a light that moved
 * (its placement changed: the driver's TrackedPlacements says so) and a room that left the house plan (the lights'
 * placements clear themselves).
 */
class LightsByRoomTest {

    private static final Instant T0 = Instant.parse("2026-11-22T19:00:00Z");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final CountingPlacements directory = new CountingPlacements();
    private final FollowMeDevice device = new FollowMeDevice(
            new DriverContext(null, "d", "FollowMeLight", logs.reporter(), new PlatformClock(() -> now)),
            directory, Duration.ofSeconds(30), Percent.of(70));
    private final List<QuietLight> lights = new ArrayList<>();
    private final Fakes.Movement sensor = new Fakes.Movement("sensor");

    /** {@code rooms} rooms "r0".. with {@code perRoom} lights each; the sensor is in r0. */
    private void flat(int rooms, int perRoom) {
        for (int r = 0; r < rooms; r++) {
            for (int i = 0; i < perRoom; i++) {
                QuietLight l = new QuietLight("light-" + r + "-" + i);
                directory.place(l.uid, "r" + r);
                device.control(l);
                lights.add(l);
            }
        }
        directory.place("sensor", "r0");
        device.use(sensor);
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
    }

    private long lookupsToLightTheRoom() {
        long before = directory.roomLookups;
        motion();
        return directory.roomLookups - before;
    }

    @Test
    void lightingARoomLooksUpOnlyTheSensorsRoomHoweverManyLightsTheFlatHas() {
        flat(10, 40);
        long lookups = lookupsToLightTheRoom();
        assertEquals(40, lights.stream().filter(l -> l.switchedOn == 1).count(), "the 40 lights of r0");
        assertTrue(lights.stream().filter(l -> l.uid.startsWith("light-0-")).allMatch(l -> l.switchedOn == 1));
        assertEquals(1, lookups, "room look-ups to light a room among 400 lights (the sensor's is the 1)");
    }

    private void motion() {
        device.movementReported(sensor, new MovementEvent(true, now));
    }

    @Test
    void aLightThatMovedIsSwitchedInItsNewRoomOnly() {
        flat(2, 1);
        QuietLight moved = lights.get(1); // light-1-0, in r1
        directory.place(moved.uid, "r0");
        device.lightMoved(moved.uid);
        directory.place("light-0-0", "r1");
        device.lightMoved("light-0-0");
        motion();
        assertEquals(List.of(0, 1), lights.stream().map(l -> l.switchedOn).toList());
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("room r0 lit (motion): on light-1-0")),
                logs.events().toString());
    }

    @Test
    void aRoomRemovedFromTheHousePlanLeavesItsLightsUnplaced() {
        flat(1, 2);
        FakeHouse house = new FakeHouse();
        device.use(house);
        directory.place("light-0-1", null); // the light's placement cleared itself: its room left the plan
        house.add("r9", "Attic"); // any change of the plan
        motion();
        assertEquals(List.of(1, 0), lights.stream().map(l -> l.switchedOn).toList());
    }
}
