package org.tinysep.followmelight.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 29, packet → light command: every light of the room gets its command before any light's name is looked up
 * for the event log (a name is read through the service registry); the words in the log are unchanged.
 */
class CommandsFirstTest {

    private static final Instant T0 = Instant.parse("2026-11-22T19:00:00Z");
    private final List<String> journal = new ArrayList<>();
    private final RecordingLogs logs = new RecordingLogs(() -> T0);

    /** Placements that journal each name look-up beside the light commands. */
    private final FakePlacements directory = new FakePlacements() {
        @Override
        public String nameOf(String deviceUid) {
            journal.add("name of " + deviceUid);
            return super.nameOf(deviceUid);
        }
    };

    @Test
    void everyCommandOfTheRoomGoesOutBeforeTheNamesAreLookedUp() {
        FollowMeDevice device = new FollowMeDevice(
                new DriverContext(null, "d", "FollowMeLight", logs.reporter(), new PlatformClock(() -> T0)),
                directory, Duration.ofSeconds(30), Percent.of(70));
        Fakes.Simple ceiling = new Fakes.Simple("ceiling", journal);
        Fakes.Dimmable reading = new Fakes.Dimmable("reading", journal);
        Fakes.Movement sensor = new Fakes.Movement("sensor");
        for (String uid : List.of("ceiling", "reading", "sensor")) {
            directory.rooms.put(uid, "lounge");
        }
        device.control(ceiling);
        device.control(reading);
        device.use(sensor);
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        journal.clear();

        sensor.report(T0.plusSeconds(1));

        assertEquals(List.of("ceiling on", "reading 70%", "name of ceiling", "name of reading"), journal);
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("room lounge lit (motion): on ceiling, reading")),
                logs.events().toString());
    }
}
