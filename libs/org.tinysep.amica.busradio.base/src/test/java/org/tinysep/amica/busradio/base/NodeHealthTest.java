package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.T0;
import static org.tinysep.amica.busradio.base.TestRadio.frame;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.health.NodePolicy;

/** Sensor health of AmICA bus devices (issue 12.1) and the node cap (issue 14), without a framework. */
class NodeHealthTest {

    private static final String FROM = "127.0.0.1:40000";
    private final TestRadio radio = new TestRadio();

    private void at(Instant t, byte[] datagram) {
        radio.handler.datagram(datagram, datagram.length, FROM, t);
    }

    private static byte[] keepAlive(int millivolts) {
        return frame(1, 17, AmicaPayloads.encode(new KeepAlive(60, millivolts, 1,
                AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 1234)));
    }

    private static byte[] motion() {
        return frame(1, 17, AmicaPayloads.encode(new MotionDetection(false)));
    }

    private List<String> problems() {
        return radio.logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).map(EventEntry::message)
                .toList();
    }

    @Test
    void aSilentMovementNodeGoesOfflineAfterTheConfiguredIntervalsAndComesBack() {
        radio.nodes.policy(new NodePolicy(3, 2200, 1000));
        at(T0, keepAlive(3000));
        AmicaBusDevice<String> node = radio.nodes.find(new AmicaAddress(1, 17));
        assertEquals(DeviceStatus.State.ONLINE, node.status().state());
        radio.nodes.checkHealth(T0.plusSeconds(5)); // movement: every 2 s, 3 missed = 6 s
        assertEquals(DeviceStatus.State.ONLINE, node.status().state());
        radio.nodes.checkHealth(T0.plusSeconds(6));
        assertEquals(DeviceStatus.State.OFFLINE, node.status().state());
        assertTrue(node.status().detail().startsWith("silent since 2026-11-22 10:00:00 UTC"), node.status().detail());
        assertEquals(1, problems().size());
        assertTrue(problems().get(0).startsWith("AmICA node 1.17 (AmICA node 1.17) has not been heard since "
                + "2026-11-22 10:00:00 UTC (6 s without a report; it promises one every 2 s"), problems().get(0));
        NodeHealth h = node.health();
        assertFalse(h.online());
        assertEquals(T0, h.silentSince());
        radio.nodes.checkHealth(T0.plusSeconds(60));
        assertEquals(1, problems().size(), "one PROBLEM per silence");

        at(T0.plusSeconds(70), motion());
        assertEquals(DeviceStatus.State.ONLINE, node.status().state());
        assertTrue(node.health().online());
        assertNull(node.health().silentSince());
        assertTrue(radio.logs.events().stream().anyMatch(e -> e.message().startsWith("heard again after 70 s")));
    }

    /**
     * Issue 25, item 6: a change-only movement node (it reports every 60 s, the platform assumes every 2 s) used to
     * go OFFLINE and ONLINE every minute: 4 entries a minute, ~5,760 a day (2.6 million a month for a home). Now
     * it is damped: after 3 silences in an hour one "Monitoring reduced" notice, its limit widened, at most one
     * summary an hour, and the normal limit again once it reports steadily.
     */
    @Test
    void aFlappingNodeIsDampedAndStopsFillingTheEventLog() {
        radio.nodes.policy(new NodePolicy(3, 2200, 1000));
        at(T0, keepAlive(3000));
        AmicaBusDevice<String> node = radio.nodes.find(new AmicaAddress(1, 17));
        int before = radio.logs.events().size();
        Instant end = T0.plus(java.time.Duration.ofDays(1));
        for (Instant t = T0.plusSeconds(1); !t.isAfter(end); t = t.plusSeconds(1)) {
            if (t.getEpochSecond() % 60 == 0) {
                at(t, motion());
            }
            radio.nodes.checkHealth(t);
        }
        List<EventEntry> day = radio.logs.events().subList(before, radio.logs.events().size());
        long offline = day.stream().filter(e -> e.message().contains("has not been heard since")).count();
        assertEquals(3, offline, "three flaps, then damped");
        assertTrue(day.size() <= 3 * 4 + 1 + 24, day.size() + " entries in a day (undamped: ~5,760)");
        List<String> notices = day.stream().map(EventEntry::message)
                .filter(m -> m.startsWith("Monitoring reduced: AmICA node 1.17")).toList();
        assertEquals(1, notices.size(), notices.toString());
        assertTrue(notices.get(0).contains("went silent and came back 3 times within an hour (it is OFFLINE after "
                + "6 s without a report)") && notices.get(0).contains("now counts as OFFLINE only after 2 min"),
                notices.get(0));
        assertTrue(day.stream().filter(e -> e.message().contains("is still flapping")).count() <= 24);
        assertEquals(DeviceStatus.State.ONLINE, node.status().state());

        // it reports steadily again: after an hour the normal limit is back, and a real silence is reported as usual
        Instant steady = end;
        for (int i = 1; i <= 3700; i += 2) {
            at(end.plusSeconds(i), motion());
            radio.nodes.checkHealth(end.plusSeconds(i));
            steady = end.plusSeconds(i);
        }
        assertTrue(radio.logs.events().stream().anyMatch(e -> e.message().equals(
                "AmICA node 1.17 (AmICA node 1.17) no longer flaps (fewer than 3 silences in the last hour); it counts "
                        + "as OFFLINE after 6 s of silence again.")));
        radio.nodes.checkHealth(steady.plusSeconds(6));
        assertEquals(DeviceStatus.State.OFFLINE, node.status().state());
    }

    @Test
    void aLowBatteryIsReportedOnceBeforeTheNodeDies() {
        at(T0, keepAlive(2600));
        at(T0.plusSeconds(60), keepAlive(2190));
        at(T0.plusSeconds(120), keepAlive(2150));
        at(T0.plusSeconds(180), keepAlive(2210)); // wobbling just above the level: not "fine again"
        AmicaBusDevice<String> node = radio.nodes.find(new AmicaAddress(1, 17));
        assertEquals(List.of("AmICA node 1.17 (AmICA node 1.17) reports a low battery: 2190 mV (low below 2200 mV)."
                + " Replace or recharge it soon, before the node stops reporting."), problems());
        assertTrue(node.health().batteryLow());
        assertEquals(2210, node.health().batteryMillivolts());
        at(T0.plusSeconds(240), keepAlive(3100));
        assertFalse(node.health().batteryLow());
        assertTrue(radio.logs.events().stream().anyMatch(e -> e.message().equals("battery fine again: 3100 mV")));
    }

    @Test
    void linkQualityAndSequenceGapsFromTheFrames() {
        at(T0, keepAlive(3000));
        // frames with sequence 7 every time (TestRadio.frame): each later one looks like 255 lost, which is a
        // restart, not loss; so send frames with increasing numbers, skipping two
        int[] seqs = {8, 9, 12, 13};
        for (int i = 0; i < seqs.length; i++) {
            byte[] f = org.tinysep.amica.protocol.AmicaCodec.encode(new org.tinysep.amica.protocol.AmicaFrame(1, 17,
                    0, seqs[i], AmicaPayloads.encode(new MotionDetection(false))));
            at(T0.plusSeconds(2L * (i + 1)), f);
        }
        NodeHealth h = radio.nodes.find(new AmicaAddress(1, 17)).health();
        assertEquals(2, h.sequenceGaps());
        assertEquals(5, h.received());
    }

    @Test
    void newNodesBeyondTheCapAreRejectedAndCountedWithOneProblem() {
        radio.nodes.policy(new NodePolicy(30, 2200, 2));
        for (int a = 1; a <= 5; a++) {
            at(T0, frame(1, a, TestRadio.keepAlive(AmicaNodeType.MOVEMENT)));
        }
        assertEquals(2, radio.nodes.size());
        assertEquals(3, radio.nodes.overCap());
        assertEquals(1, problems().size());
        assertTrue(problems().get(0).startsWith("node 1.3 (via route 127.0.0.1:40000) not created: this bus radio "
                + "already has 2 nodes, its limit (maxNodes = 2)"), problems().get(0));
        assertEquals(3, radio.logs.packets().stream().filter(p -> p.note().contains("would exceed maxNodes")).count());
        at(T0, frame(1, 1, TestRadio.keepAlive(AmicaNodeType.MOVEMENT)));
        assertEquals(3, radio.nodes.overCap(), "known nodes still get through");
    }

    /**
     * Issue 29 (idle CPU): a tick looks through the nodes only when the first of them is due. 20 movement nodes heard
     * once: one round on the first tick, none until their limit (6 s), one that finds all 20 silent, none in the
     * minute after; a node heard again brings the next tick's round.
     */
    @Test
    void aTickLooksThroughTheNodesOnlyWhenOneIsDue() {
        radio.nodes.policy(new NodePolicy(3, 2200, 1000));
        for (int i = 1; i <= 20; i++) {
            byte[] f = frame(1, i, AmicaPayloads.encode(new KeepAlive(60, 3000, 1,
                    AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 1000 + i)));
            at(T0, f);
        }
        long start = radio.nodes.healthRounds();
        for (int s = 1; s <= 5; s++) {
            radio.nodes.checkHealth(T0.plusSeconds(s));
        }
        assertEquals(1, radio.nodes.healthRounds() - start, "rounds in the 5 s after the nodes were heard");
        radio.nodes.checkHealth(T0.plusSeconds(6));
        assertEquals(20, problems().size(), "all 20 silent after 3 missed intervals of 2 s");
        for (int s = 7; s <= 66; s++) {
            radio.nodes.checkHealth(T0.plusSeconds(s));
        }
        assertEquals(2, radio.nodes.healthRounds() - start, "rounds in a minute of silent nodes");
        at(T0.plusSeconds(70), frame(1, 5, AmicaPayloads.encode(new MotionDetection(false))));
        radio.nodes.checkHealth(T0.plusSeconds(71));
        assertEquals(3, radio.nodes.healthRounds() - start, "a node heard again: the next tick looks");
        for (int s = 72; s <= 76; s++) {
            radio.nodes.checkHealth(T0.plusSeconds(s));
        }
        assertEquals(21, problems().size(), "and finds it silent again at its limit");
    }
}
