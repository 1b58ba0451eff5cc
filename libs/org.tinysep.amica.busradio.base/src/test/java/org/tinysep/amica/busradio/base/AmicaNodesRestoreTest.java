package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;

/** Known nodes re-created from their backups before the transport opens (docs/backup.md). */
class AmicaNodesRestoreTest {

    private static final Instant SEEN = Instant.parse("2026-11-21T22:10:00Z");
    private final TestRadio radio = new TestRadio();

    /** The backup a bus device of a simple-light node 1.20, heard by the test radio, makes of itself. */
    private ComponentBackup savedLight() {
        radio.feed(frame(1, 20, keepAlive(AmicaNodeType.SIMPLE_LIGHT)), "route-a");
        ComponentBackup b = radio.nodes.find(new AmicaAddress(1, 20)).backup();
        return new ComponentBackup(b.uid(), b.kind(), b.driverUid(), b.driverName(), b.type(), "Kitchen light",
                b.parameters(), b.nodeAddress(), b.nodeTypes(), SEEN, b.state(), b.savedAt());
    }

    @Test
    void aSavedNodeComesBackOfflineWithItsTypesAndLastSeenUntilItIsHeard() {
        ComponentBackup saved = savedLight();
        assertEquals("1.20", saved.nodeAddress());
        assertEquals(List.of("simple-light"), saved.nodeTypes());
        TestRadio restarted = new TestRadio();

        assertEquals(1, restarted.nodes.restore(List.of(saved)));

        AmicaBusDevice<String> light = restarted.nodes.find(new AmicaAddress(1, 20));
        assertEquals(saved.uid(), light.uid());
        assertEquals(Set.of("simple-light"), light.nodeTypes());
        assertEquals(DeviceStatus.State.OFFLINE, light.status().state());
        assertEquals("not heard since restart (last seen " + SEEN + ")", light.status().detail());
        assertEquals(SEEN, light.backup().lastSeen());
        assertEquals(saved.state(), light.backup().state(), "the last keep-alive is kept");

        light.send(AmicaPayloads.encode(new LightControl(40)));
        assertEquals(List.of(), restarted.transmitted, "no route until the node is heard");
        assertEquals(1, restarted.nodes.failed());
        assertTrue(restarted.logs.packets().get(0).note().contains("not heard since restart"));

        restarted.feed(frame(1, 20, AmicaPayloads.encode(new LightControl(0))), "route-b");
        assertEquals(DeviceStatus.State.ONLINE, light.status().state());
        assertEquals(1, restarted.nodes.size(), "the restored device, not a new one");
    }

    @Test
    void anUnusableBackupIsReportedAndTheOthersAreRestored() {
        ComponentBackup good = savedLight();
        ComponentBackup bad = new ComponentBackup("bad-uid", good.kind(), good.driverUid(), good.driverName(),
                good.type(), "broken", Map.of(), "1.21", List.of(), null, Map.of(), good.savedAt());
        TestRadio restarted = new TestRadio();

        assertEquals(1, restarted.nodes.restore(List.of(bad, good)));

        assertEquals(1, restarted.nodes.size());
        assertTrue(restarted.logs.events().stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().contains("cannot re-create node 1.21 (bad-uid)")), restarted.logs.events()::toString);
    }
}
