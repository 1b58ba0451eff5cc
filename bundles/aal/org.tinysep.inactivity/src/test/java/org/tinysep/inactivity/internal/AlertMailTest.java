package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.health.UnmonitoredRoom;
import org.tinysep.api.service.InactivityAlert;

/** Issue 12.2: an inactivity alert names every room that could not be watched, and says why. */
class AlertMailTest {

    private static final Instant T = Instant.parse("2026-11-25T09:12:00Z");
    private static final InactivityAlert ALERT = new InactivityAlert("r1", "Kitchen", "movement in Kitchen", T,
            T.plusSeconds(3600), "");

    @Test
    void anAlertNamesTheRoomsThatCouldNotBeWatched() {
        List<UnmonitoredRoom> rooms = new ArrayList<>();
        AlertMail words = new AlertMail(ZoneOffset.UTC, () -> rooms);
        assertFalse(words.body(ALERT).contains("Could not be watched"), "every room heard: no such line");
        assertEquals("", words.why(ALERT));

        rooms.add(new UnmonitoredRoom("r2", "Bathroom", T.plusSeconds(600), List.of("bus-1")));
        String body = words.body(ALERT);
        assertTrue(body.contains("Could not be watched: Bathroom (no sensor heard since 09:22). Sensors there are "
                + "offline (battery or radio), so activity there would not have been seen.\n"), body);
        assertEquals("; could not be watched: Bathroom (no sensor heard since 09:22)", words.why(ALERT));
    }

    @Test
    void aFailingSensorHealthDoesNotStopTheAlert() {
        AlertMail words = new AlertMail(ZoneOffset.UTC, () -> {
            throw new IllegalStateException("Sensor Health is stopping");
        });
        assertTrue(words.body(ALERT).startsWith("Inactivity Recognition raised an alert"));
        assertEquals("", words.why(ALERT));
    }
}
