package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The last activity per room survives a restart through the device's backup state. */
class RoomActivityTest {

    private static final Instant T = Instant.parse("2026-11-23T06:48:57Z");

    @Test
    void theLimitsExplanationSurvivesARestart() {
        Activity bath = new Activity("bath-uid", "Bathroom", "movement by Bath sensor", T, Duration.ofMinutes(25),
                "usually at most 10 min between 13:00 and 16:00 in Bathroom, from 9 days");
        Map<String, String> state = new RoomActivity().state(bath, null, null);
        RoomActivity.Saved saved = new RoomActivity().restore(state, new ArrayList<>());
        assertEquals(bath.explanation(), saved.last().explanation());
    }

    @Test
    void perRoomTimesAndTheLastActivityRoundTripThroughTheBackupState() {
        RoomActivity rooms = new RoomActivity();
        Activity bath = new Activity("bath-uid", "Bathroom", "movement by Bath sensor", T, Duration.ofMinutes(45));
        rooms.seen(new Activity("hall-uid", "Hall", "door", T.minusSeconds(60), Duration.ofMinutes(30)));
        rooms.seen(bath);
        rooms.seen(new Activity("bath-uid", "Bathroom", "racing report", T.minusSeconds(1), Duration.ofMinutes(45)));
        rooms.seen(new Activity("", "unknown room", "no room", T, Duration.ofMinutes(45)));
        Map<String, String> state = rooms.state(bath, T.minusSeconds(3600), T.minusSeconds(600));
        assertEquals(Map.of("room.hall-uid", T.minusSeconds(60).toString(), "room.bath-uid", T.toString(),
                "last.at", T.toString(), "last.room", "bath-uid", "last.roomName", "Bathroom",
                "last.description", "movement by Bath sensor", "last.limitSeconds", "2700",
                "watching.from", T.minusSeconds(3600).toString(), "alert.handedOver", T.minusSeconds(600).toString()),
                state);

        RoomActivity restarted = new RoomActivity();
        List<String> problems = new ArrayList<>();
        RoomActivity.Saved saved = restarted.restore(state, problems);
        assertEquals(new RoomActivity.Saved(new Activity("bath-uid", "Bathroom",
                "movement by Bath sensor (before restart)", T, Duration.ofMinutes(45)), T.minusSeconds(3600),
                T.minusSeconds(600)), saved);
        assertEquals(rooms.describe(), restarted.describe());
        assertEquals(List.of(), problems);
        assertNull(new RoomActivity().restore(Map.of(), problems).last());
    }

    @Test
    void aBadEntryIsSkippedWithAProblemAndFreshActivityReplacesATimeFromTheFuture() {
        RoomActivity rooms = new RoomActivity();
        List<String> problems = new ArrayList<>();
        RoomActivity.Saved saved = rooms.restore(Map.of("room.bath-uid", "2099-01-01T00:00:00Z",
                "room.hall-uid", "yesterday", "last.at", "2099-01-01T00:00:00Z", "last.limitSeconds", "ninety"),
                problems);
        assertEquals("{bath-uid=2099-01-01T00:00:00Z}", rooms.describe(), "a record of what was seen, as saved");
        assertNull(saved.last());
        assertEquals(2, problems.size(), problems.toString());
        assertTrue(problems.get(0).contains("yesterday") || problems.get(1).contains("yesterday"), problems.toString());

        // after the clock went back, a room's fresh activity replaces its time from the future
        RoomActivity live = new RoomActivity();
        live.seen(new Activity("bath-uid", "Bathroom", "virtual", Instant.parse("2099-01-01T00:00:00Z"),
                Duration.ofMinutes(45)));
        live.seen(new Activity("bath-uid", "Bathroom", "real", T, Duration.ofMinutes(45)));
        assertEquals("{bath-uid=" + T + "}", live.describe());
    }
}
