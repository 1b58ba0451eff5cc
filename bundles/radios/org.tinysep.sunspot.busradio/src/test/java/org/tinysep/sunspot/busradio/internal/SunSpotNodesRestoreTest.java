package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** Known Sun SPOTs re-created from their backups before the links open (docs/backup.md). */
class SunSpotNodesRestoreTest {

    private static final Instant SEEN = Instant.parse("2026-11-21T22:10:00Z");

    @Test
    void aSavedSpotComesBackOfflineWithAllItsSensorTypesUntilItIsHeard() {
        TestBus before = new TestBus();
        before.feed(frame(SPOT_A, new TemperatureStatus(21.5)), "udp a");
        before.feed(frame(SPOT_A, new LightStatus(40)), "udp a");
        ComponentBackup b = before.node(SPOT_A).backup();
        ComponentBackup saved = new ComponentBackup(b.uid(), b.kind(), b.driverUid(), b.driverName(), b.type(),
                b.name(), b.parameters(), b.nodeAddress(), b.nodeTypes(), SEEN, b.state(), b.savedAt());
        TestBus after = new TestBus();

        assertEquals(1, after.nodes.restore(List.of(saved)));

        SunSpotBusDevice spot = after.node(SPOT_A);
        assertEquals(b.uid(), spot.uid());
        assertEquals(Set.of("temperature", "light-sensor"), spot.nodeTypes());
        assertEquals(DeviceStatus.State.OFFLINE, spot.status().state());
        assertEquals("not heard since restart (last seen " + SEEN + ")", spot.status().detail());
        after.feed(frame(SPOT_A, new TemperatureStatus(22)), "udp b");
        assertSame(spot, after.node(SPOT_A));
        assertEquals(DeviceStatus.State.ONLINE, spot.status().state());
        assertEquals(1, after.nodes.size());
    }

    @Test
    void aBackupWithAnUnknownNodeTypeIsReportedAndSkipped() {
        TestBus after = new TestBus();
        ComponentBackup bad = new ComponentBackup("x", org.tinysep.api.backup.ComponentKind.DEVICE, "driver-uid",
                "BusRadioSunSpot", "BusRadioSunSpot", "x", Map.of(), SPOT_A.toString(), List.of("teleporter"), null,
                Map.of(), SEEN);
        assertEquals(0, after.nodes.restore(List.of(bad)));
        assertEquals(0, after.nodes.size());
        assertTrue(after.problems().stream().anyMatch(p -> p.contains("unknown node type teleporter")),
                after.problems()::toString);
    }
}
