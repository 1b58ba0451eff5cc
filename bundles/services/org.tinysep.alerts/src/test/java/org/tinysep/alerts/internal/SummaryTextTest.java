package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Set;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.SensorHealth;

/** The daily summary names the nodes whose battery is low (Sensor Health), or says it cannot know. */
class SummaryTextTest {

    private static final Instant NOW = Instant.parse("2026-11-25T08:00:00Z");

    @TempDir
    Path state;

    @Test
    void lowBatteriesAreNamedWithTheirRoomAndVoltage() {
        SummaryText text = new SummaryText(new AlertText(ZoneOffset.UTC), state);
        NodeHealth low = new NodeHealth("bus-1", "1.21", Set.of("movement"), true, NOW, null, Duration.ofSeconds(2),
                2150, true, 10, 10, 0);
        String body = text.body(NOW, NOW, false, List.of(), List.of(),
                List.of(new SensorHealth(low, "Bathroom motion", "r1", "Bathroom")), List.of());
        assertTrue(body.contains("\nLow batteries: 1\n  Bathroom motion in Bathroom: 2150 mV, replace or recharge it "
                + "soon\n"), body);
        assertTrue(text.body(NOW, NOW, false, List.of(), List.of(), List.of(), List.of())
                .contains("\nLow batteries: none\n"));
    }

    @Test
    void withoutSensorHealthTheSummarySaysItCannotKnow() {
        String body = new SummaryText(new AlertText(ZoneOffset.UTC), state).body(NOW, NOW, false, List.of(), List.of(),
                null, List.of());
        assertTrue(body.contains("Low batteries: not known (Sensor Health, which reads the nodes' battery levels, is "
                + "not running)"), body);
    }

    @Test
    void monitoringReducedSinceTheLastSummaryIsListedInPlainWords() {
        SummaryText text = new SummaryText(new AlertText(ZoneOffset.UTC), state);
        EventEntry e = new EventEntry(7, NOW, EventKind.PROBLEM, "drivers-list", "Monitoring reduced: Inactivity "
                + "Recognition (org.tinysep.inactivity) was stopped: nobody is told if the person stops moving");
        String body = text.body(NOW, NOW, false, List.of(), List.of(), List.of(), List.of(e));
        assertTrue(body.contains("\nMonitoring reduced since the last summary: 1\n  " + new AlertText(ZoneOffset.UTC).fullTime(NOW) + ": "
                + "Inactivity Recognition (org.tinysep.inactivity) was stopped"), body);
        assertTrue(text.body(NOW, NOW, false, List.of(), List.of(), List.of(), List.of())
                .contains("\nMonitoring reduced since the last summary: nothing\n"));
        assertTrue(text.body(NOW, NOW, false, List.of(), List.of(), List.of(), null)
                .contains("Monitoring reduced since the last summary: not known"));
    }
}
