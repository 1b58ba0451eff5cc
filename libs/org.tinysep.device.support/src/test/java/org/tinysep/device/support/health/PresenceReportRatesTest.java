package org.tinysep.device.support.health;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.NodeType;

/** Issue 11: a presence node repeats its Reed-Switch Status every second, like a reed switch. */
class PresenceReportRatesTest {

    @Test
    void aPresenceNodeIsHeardEverySecond() {
        for (String type : Set.of(NodeType.PRESENCE_BED, NodeType.PRESENCE_SEAT, NodeType.PRESENCE_FLUSH,
                NodeType.PRESENCE_APPLIANCE)) {
            assertEquals(Duration.ofSeconds(1), ReportRates.interval(Set.of(type), Duration.ofMinutes(1)), type);
            assertEquals(1.0, ReportRates.perSecond(Set.of(type)), 1e-9, type);
        }
        assertEquals(1.5, ReportRates.perSecond(Set.of(NodeType.PRESENCE_SEAT, NodeType.MOVEMENT)), 1e-9);
        assertEquals(Duration.ofMinutes(1), ReportRates.interval(Set.of("presence"), Duration.ofMinutes(1)),
                "not a presence type: the keep-alive period");
    }
}
