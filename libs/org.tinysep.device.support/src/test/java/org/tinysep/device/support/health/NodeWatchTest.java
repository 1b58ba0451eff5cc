package org.tinysep.device.support.health;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.NodeType;

class NodeWatchTest {

    private static final Instant T0 = Instant.parse("2026-01-05T09:00:00Z");

    @Test
    void ratesFollowTheThesisNodeTypes() {
        assertEquals(Duration.ofSeconds(2), ReportRates.interval(Set.of(NodeType.MOVEMENT), Duration.ofMinutes(1)));
        assertEquals(Duration.ofSeconds(1), ReportRates.interval(Set.of(NodeType.MOVEMENT, NodeType.DOOR),
                Duration.ofMinutes(1)));
        assertEquals(Duration.ofSeconds(10), ReportRates.interval(Set.of(NodeType.TEMPERATURE), Duration.ZERO));
        assertEquals(Duration.ofMinutes(1), ReportRates.interval(Set.of(), Duration.ofMinutes(1)));
        assertEquals(0.5, ReportRates.perSecond(Set.of(NodeType.MOVEMENT)), 1e-9);
        assertEquals(Duration.ofSeconds(2), ReportRates.interval(Set.of(NodeType.PERSON), Duration.ofMinutes(1)),
                "a person node sends a movement summary every 2 s (issue 26)");
    }

    @Test
    void silentAfterTheConfiguredIntervalsAndHeardAgain() {
        NodeWatch w = new NodeWatch(Duration.ofSeconds(2), 0.5, null);
        assertFalse(w.checkSilence(T0, 3), "never heard: not silent (it may not exist yet)");
        w.heard(T0, -1);
        assertFalse(w.checkSilence(T0.plusSeconds(5), 3));
        assertTrue(w.checkSilence(T0.plusSeconds(6), 3));
        assertEquals(T0, w.silentSince());
        assertFalse(w.checkSilence(T0.plusSeconds(7), 3), "once per silence");
        assertEquals(T0, w.heard(T0.plusSeconds(8), -1), "the frame ends the silence that began at T0");
        assertNull(w.silentSince());
        assertNull(w.heard(T0.plusSeconds(9), -1));
    }

    @Test
    void aRealTimeGuardKeepsALaggingReceiverFromLookingSilentInVirtualTime() {
        NodeWatch w = new NodeWatch(Duration.ofSeconds(2), 0.5, null);
        w.realSilenceGuard(Duration.ofHours(1));
        w.heard(T0, -1);
        assertFalse(w.checkSilence(T0.plusSeconds(3600), 3), "an hour of platform time in a moment of real time");
        w.realSilenceGuard(Duration.ZERO);
        assertTrue(w.checkSilence(T0.plusSeconds(3600), 3));
    }

    @Test
    void theClockGoingBackDoesNotFreezeTheSilenceCheck() {
        NodeWatch w = new NodeWatch(Duration.ofSeconds(2), 0.5, null);
        w.heard(T0, -1);
        Instant back = T0.minusSeconds(3600);
        assertFalse(w.checkSilence(back, 3));
        assertTrue(w.checkSilence(back.plusSeconds(6), 3));
    }

    @Test
    void linkQualityCountsReceivedAgainstPromisedReports() {
        NodeWatch w = new NodeWatch(Duration.ofSeconds(2), 0.5, null);
        // a movement node at position 6 of thesis Table 5.4: about 60 % of the frames arrive
        for (int s = 0; s < 300; s += 2) {
            if (s % 10 != 2 && s % 10 != 6) {
                w.heard(T0.plusSeconds(s), -1);
            }
        }
        Instant end = T0.plusSeconds(299);
        assertEquals(150, w.expected(end));
        assertEquals(90, w.received(end));
        assertEquals("60 % (90 of 150 expected reports in the last 5 min)", w.describeQuality(end));
        assertEquals(0, w.received(end.plusSeconds(400)), "frames older than the window do not count");
    }

    @Test
    void sequenceGapsCountMissingFramesAcrossTheWrap() {
        NodeWatch w = new NodeWatch(Duration.ofSeconds(2), 0.5, null);
        w.heard(T0, 250);
        w.heard(T0.plusSeconds(2), 253); // 251, 252 missing
        w.heard(T0.plusSeconds(4), 1); // 254, 255, 0 missing
        w.heard(T0.plusSeconds(6), 0); // out of order or restart: not counted as loss
        assertEquals(5, w.sequenceGaps());
    }

    /** Issue 25, item 6: three silences within an hour widen the limit to twice the longest; steady reports undo it. */
    @Test
    void aFlappingNodesSilenceLimitIsWidenedAndComesBack() {
        NodeWatch w = new NodeWatch(Duration.ofSeconds(2), 0.5, null);
        w.heard(T0, -1);
        int declared = 0;
        Instant t = T0;
        for (int s = 1; s <= 3600; s++) {
            t = T0.plusSeconds(s);
            if (s % 40 == 0) {
                w.heard(t, -1);
            }
            declared += w.checkSilence(t, 3) ? 1 : 0;
        }
        assertEquals(3, declared, "OFFLINE three times, then damped");
        assertEquals(40, w.missedIntervals(3, t), "twice the longest silence (40 s) in 2 s intervals");
        String notice = w.flapping("Node 7", t);
        assertTrue(notice.startsWith("Monitoring reduced: Node 7 went silent and came back "), notice);
        assertNull(w.flapping("Node 7", t.plusSeconds(1)), "one notice, then at most one line an hour");
        for (int s = 1; s <= 3601; s++) {
            w.heard(t.plusSeconds(s), -1);
        }
        assertEquals(3, w.missedIntervals(3, t.plusSeconds(3601)), "an hour without a silence: the normal limit");
        assertTrue(w.flapping("Node 7", t.plusSeconds(3601)).startsWith("Node 7 no longer flaps"));
    }
}
