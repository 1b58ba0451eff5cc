package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The last activity per room survives a restart through the device's backup state. */
class RoomActivityTest {

    private static final Instant T = Instant.parse("2026-11-23T06:48:57Z");

    @Test
    void perRoomTimesAndTheLastActivityRoundTripThroughTheBackupState() {
        RoomActivity rooms = new RoomActivity();
        Activity bath = new Activity("bath-uid", "Bathroom", "movement by Bath sensor", T, Duration.ofMinutes(45));
        rooms.seen(new Activity("hall-uid", "Hall", "door", T.minusSeconds(60), Duration.ofMinutes(30)));
        rooms.seen(bath);
        rooms.seen(new Activity("bath-uid", "Bathroom", "late report", T.minusSeconds(5), Duration.ofMinutes(45)));
        rooms.seen(new Activity("", "unknown room", "no room", T, Duration.ofMinutes(45)));
        Map<String, String> state = rooms.state(bath);
        assertEquals(Map.of("room.hall-uid", T.minusSeconds(60).toString(), "room.bath-uid", T.toString(),
                "last.at", T.toString(), "last.room", "bath-uid", "last.roomName", "Bathroom",
                "last.description", "movement by Bath sensor", "last.limitSeconds", "2700"), state);

        RoomActivity restarted = new RoomActivity();
        Activity last = restarted.restore(state);
        assertEquals(new Activity("bath-uid", "Bathroom", "movement by Bath sensor (before restart)", T,
                Duration.ofMinutes(45)), last);
        assertEquals(rooms.describe(), restarted.describe());
        assertNull(new RoomActivity().restore(Map.of()));
    }
}
