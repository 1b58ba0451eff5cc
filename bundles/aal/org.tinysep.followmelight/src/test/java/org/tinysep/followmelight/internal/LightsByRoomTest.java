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
import org.tinysep.device.support.time.PlatformClock;

/**
 * The packet → light command path: finding a room's lights is one index read, not a look-up of every light's room
 * per switching, so it costs the same with 4 lights in the flat or 400 ({@link LightIndexFollowsMovesTest}: the
 * index follows lights that move and rooms that leave the house plan).
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
        device.movementReported(sensor, new MovementEvent(true, now));
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
}
