package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.json.JsonWriter;

/**
 * Issue 26 item 7, the caregiver page's JSON: HELP and FALL alerts carry what they are about and their explanation
 * in words; each person node its wearer, its last report and its battery, in words too.
 */
class PersonAlertsJsonTest {

    private static final Instant T = Instant.parse("2026-11-29T14:03:00Z");
    private static final String FALL_TEXT = "a fall of Anna was detected at 14:02: a hard impact (3.5 g), then lying "
            + "still for 6 s; the body turned by 88° from how it was before the impact (node 0014.4F01.0000.0A04); "
            + "last seen in the Bathroom at 14:01 by its motion sensor. Please check on Anna.";

    @Test
    void fallAndHelpAlertsSayWhatTheyAreAboutAndExplainThemselves() {
        Alert fall = new Alert("7", AlertKind.FALL, "falldetection:u", "", "", T, "Fall: Anna fell at 14:02",
                FALL_TEXT, AlertState.OPEN, 1, null, "", List.of());
        Map<String, Object> j = AlertsApi.json(fall);
        assertEquals("FALL", j.get("kind"));
        assertEquals("fall (the person may have fallen)", j.get("kindWords"));
        assertEquals(FALL_TEXT, j.get("explanation"));
        assertTrue(JsonWriter.write(j).contains("\"kindWords\":\"fall (the person may have fallen)\""),
                JsonWriter.write(j));
        Alert help = new Alert("8", AlertKind.HELP, "help:0014.4F01.0000.0A04", "", "", T,
                "TinySEP: Anna asks for help (help button, 14:03:00)", "", AlertState.OPEN, 0, null, "", List.of());
        Map<String, Object> h = AlertsApi.json(help);
        assertEquals("help button (the person asked for help)", h.get("kindWords"));
        assertEquals("TinySEP: Anna asks for help (help button, 14:03:00)", h.get("explanation"),
                "an alert without a text is explained by its subject");
    }

    private static final PersonWatchWords.Source NO_INACTIVITY = new PersonWatchWords.Source(false, null);

    @Test
    void aPersonNodeShowsItsWearerLastReportAndBatteryInWords() {
        NodeHealth sunSpot = new NodeHealth("bus-1", "0014.4F01.0000.0A04", Set.of("person"), true,
                T.minusSeconds(3), null, Duration.ofSeconds(2), null, false, 30, 30, 0);
        Map<String, Object> j = PersonNodes.json(new PersonNodes.Node("dev-1", "Person node 0014.4F01.0000.0A04",
                "Anna", "0014.4F01.0000.0A04", T.minusSeconds(5), sunSpot, NO_INACTIVITY), T);
        assertEquals("Anna", j.get("person"));
        assertEquals(T.minusSeconds(3), j.get("lastReport"), "the newest frame of the node, not only its summaries");
        assertEquals("last report 3 s ago", j.get("lastReportWords"));
        assertNull(j.get("batteryMillivolts"));
        assertTrue(((String) j.get("batteryWords")).startsWith("not reported (the node's protocol carries no battery"),
                (String) j.get("batteryWords"));
        assertTrue(j.containsKey("worn") && j.get("worn") == null, "worn: not known without Inactivity Recognition");
        assertEquals("not known: Inactivity Recognition is not running (it tells whether the node is worn)",
                j.get("wornWords"));
        assertTrue(((String) j.get("summary")).startsWith("Anna's person node (0014.4F01.0000.0A04): last report 3 s "
                + "ago; battery not reported"), (String) j.get("summary"));

        NodeHealth low = new NodeHealth("bus-2", "1.30", Set.of("person"), false, T.minus(Duration.ofMinutes(50)),
                T.minus(Duration.ofMinutes(50)), Duration.ofSeconds(2), 3410, true, 0, 30, 0);
        Map<String, Object> k = PersonNodes.json(new PersonNodes.Node("dev-2", "Pendant", "", "1.30", null, low,
                new PersonWatchWords.Source(true, null)), T);
        assertEquals("nobody is named as its wearer (set the node's parameter 'person')", k.get("personWords"));
        assertEquals("not known: the node has no wearer's name, so its movement is nobody's activity",
                k.get("wornWords"));
        assertEquals("last report 50 min ago, silent now: the node is off, out of range or its battery is empty",
                k.get("lastReportWords"));
        assertEquals(3410, k.get("batteryMillivolts"));
        assertEquals("3.41 V, LOW: charge or replace it soon", k.get("batteryWords"));

        Map<String, Object> none = PersonNodes.json(new PersonNodes.Node("dev-3", "P", "Ben", "x", null, null,
                NO_INACTIVITY), T);
        assertEquals("no report since the platform started", none.get("lastReportWords"));
        assertEquals("not known (no health of this node from its bus radio)", none.get("batteryWords"));
    }
}
