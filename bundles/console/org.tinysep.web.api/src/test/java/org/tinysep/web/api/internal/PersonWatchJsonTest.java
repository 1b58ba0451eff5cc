package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.json.JsonWriter;

/**
 * Issue 26 items 4 and 7: the caregiver page's person-node card says, from Inactivity Recognition's
 * {@code persons()}, whether the node is worn (or since when it seems not to be), its last movement, where its
 * wearer was last seen and the wearer's own watch, in plain words.
 */
class PersonWatchJsonTest {

    private static final Instant T = Instant.parse("2026-11-29T14:03:00Z");
    private static final String ANNA = "0014.4F01.0000.0A04";

    private static Map<String, Object> card(String person, PersonWatchWords.Source s) {
        return PersonNodes.json(new PersonNodes.Node("dev-1", "Person node " + ANNA, person, ANNA, T.minusSeconds(2),
                null, s), T);
    }

    @Test
    void aWornNodeSaysSoWithItsLastMovementRoomAndWatch() {
        PersonWatch w = new PersonWatch("Anna", "dev-1", true, T.minusSeconds(4), Optional.of("Kitchen"),
                InactivityState.WATCHING);
        Map<String, Object> j = card("Anna", new PersonWatchWords.Source(true, w));
        assertEquals(true, j.get("worn"));
        assertEquals("yes: its movement counts as Anna's activity", j.get("wornWords"));
        assertEquals(T.minusSeconds(4), j.get("lastMovement"));
        assertEquals("4 s ago", j.get("lastMovementWords"));
        assertEquals("Kitchen", j.get("lastRoom"));
        assertEquals("last seen in the Kitchen", j.get("lastRoomWords"));
        assertEquals(InactivityState.WATCHING, j.get("watch"));
        assertEquals("watching: an alert if Anna is not active for longer than the limit of the Kitchen",
                j.get("watchWords"));
        assertTrue(((String) j.get("summary")).endsWith("; worn: yes: its movement counts as Anna's activity; last "
                + "movement 4 s ago; last seen in the Kitchen; watching: an alert if Anna is not active for longer than "
                + "the limit of the Kitchen."), (String) j.get("summary"));
        String json = JsonWriter.write(j);
        assertTrue(json.contains("\"worn\":true,") && json.contains("\"watch\":\"WATCHING\""), json);
        assertFalse(json.contains("not known here yet"), "the placeholder is gone: " + json);
    }

    @Test
    void aNodeNotWornSaysSinceWhenItLayStillAndThatTheRoomSensorsWatch() {
        Instant still = T.minus(Duration.ofMinutes(130));
        PersonWatch w = new PersonWatch("Anna", "dev-1", false, still, Optional.of("Living room"),
                InactivityState.WATCHING);
        Map<String, Object> j = card("Anna", new PersonWatchWords.Source(true, w));
        assertEquals(false, j.get("worn"));
        assertEquals(still, j.get("lastMovement"), "the page says 'seems not worn since' this time");
        assertEquals("seems not to be worn: it has not moved for 2 h 10 min while the room sensors saw someone; until "
                + "it moves again, Anna is watched by the room sensors", j.get("wornWords"));
        assertEquals("2 h ago", j.get("lastMovementWords"));
        assertEquals("last seen in the Living room", j.get("lastRoomWords"));
    }

    @Test
    void anAlertAndAWearerNotSeenInARoomYetAreSaidInWords() {
        PersonWatch w = new PersonWatch("Bert", "dev-1", true, T.minus(Duration.ofMinutes(50)), Optional.empty(),
                InactivityState.ALERT);
        Map<String, Object> j = card("Bert", new PersonWatchWords.Source(true, w));
        assertEquals(InactivityState.ALERT, j.get("watch"));
        assertEquals("ALERT: Bert has not been active for longer than the limit of the room where Bert was last seen; "
                + "help was called", j.get("watchWords"));
        assertNull(j.get("lastRoom"));
        assertEquals("not seen in a room yet: no room sensor's activity has been counted as Bert's",
                j.get("lastRoomWords"));
        assertEquals("50 min ago", j.get("lastMovementWords"));

        PersonWatch home = new PersonWatch("Bert", "dev-1", true, T, Optional.empty(), InactivityState.NOT_WATCHING);
        assertEquals("not watching: nobody seems to be home",
                card("Bert", new PersonWatchWords.Source(true, home)).get("watchWords"));
    }

    @Test
    void aNodeInactivityRecognitionHasNotHeardYetIsNotKnownYet() {
        Map<String, Object> j = card("Anna", new PersonWatchWords.Source(true, null));
        assertTrue(j.containsKey("worn") && j.get("worn") == null, "not known yet: " + j);
        assertEquals("not known yet: Inactivity Recognition has had no movement summary of this node yet",
                j.get("wornWords"));
        assertEquals("not watched on their own yet (Anna's node has not reported to Inactivity Recognition yet)",
                j.get("watchWords"));
        assertEquals("not watched: Inactivity Recognition is not running",
                card("Anna", new PersonWatchWords.Source(false, null)).get("watchWords"));
    }

    @Test
    void spansReadNaturally() {
        assertEquals("45 s", PersonWatchWords.span(Duration.ofSeconds(45)));
        assertEquals("12 min", PersonWatchWords.span(Duration.ofMinutes(12)));
        assertEquals("2 h", PersonWatchWords.span(Duration.ofMinutes(120)));
        assertEquals("0 s", PersonWatchWords.span(Duration.ofSeconds(-5)), "a time after now is no negative span");
    }
}
