package org.tinysep.device.support.health;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
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

    /**
     * Issue 29 (idle CPU): a tick looks at a node only when its checks can say something. Two watches get the same
     * frames (steady, silent, back, flapping, the clock going back); one is checked on every tick, the other only
     * when {@link NodeWatch#due}: both declare the same silences and write the same notices, at the same ticks,
     * and the gated one is looked at a fraction as often (every tick only while it flaps).
     */
    @Test
    void aTickLooksAtANodeOnlyWhenSomethingIsDue() {
        NodeWatch every = new NodeWatch(Duration.ofSeconds(10), 0.1, null);
        NodeWatch gated = new NodeWatch(Duration.ofSeconds(10), 0.1, null);
        List<String> seenEvery = new ArrayList<>();
        List<String> seenGated = new ArrayList<>();
        int looks = 0;
        int quietLooks = 0; // in the first 20 minutes: 10 steady, 10 silent
        Instant t = T0;
        for (int s = 1; s <= 4 * 3600; s++) {
            t = s == 3 * 3600 ? t.minusSeconds(1800) : t.plusSeconds(1); // the clock goes back once
            boolean frame = s < 600 ? s % 10 == 0 // steady
                    : s < 1200 ? false // silent for 10 minutes
                    : s < 2 * 3600 ? s % 45 == 0 // flapping: every 45 s against a 30 s limit
                    : s % 10 == 0 || s > 3 * 3600; // steady again
            if (frame) {
                every.heard(t, -1);
                gated.heard(t, -1);
            }
            check(every, t, s, seenEvery);
            if (gated.due(t, 3)) {
                looks++;
                quietLooks += s <= 1200 ? 1 : 0;
                check(gated, t, s, seenGated);
            }
        }
        assertEquals(seenEvery, seenGated, "the same silences and notices at the same ticks");
        assertTrue(seenEvery.stream().anyMatch(e -> e.contains("silent")), "the run has a silence: " + seenEvery);
        assertTrue(seenEvery.stream().anyMatch(e -> e.contains("no longer flaps")), "and a flap's end: " + seenEvery);
        assertTrue(quietLooks <= 1200 / 20, "steady, then silent: looked at on " + quietLooks + " of 1200 ticks");
        assertTrue(looks < 4 * 3600, "looked at on " + looks + " of " + 4 * 3600 + " ticks (flapping: each)");
    }

    private static void check(NodeWatch w, Instant t, int tick, List<String> seen) {
        if (w.checkSilence(t, 3)) {
            seen.add(tick + " silent since " + w.silentSince());
        }
        String notice = w.flapping("Node 7", t);
        if (notice != null) {
            seen.add(tick + " " + notice);
        }
    }
}
