package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
import static org.tinysep.amica.protocol.AmicaNodeType.PET_COLLAR;

import java.time.Instant;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;

/**
 * Issue 25, item 1: one unauthenticated keep-alive claiming other node types must not re-type a node that devices
 * depend on (it would remove them); it is counted, reported once per claim, and the installer confirms a real change.
 */
class NodeTypeGuardTest {

    private static final String NODE = "route 127.0.0.1:40000";
    private static final String FORGER = "127.0.0.1:6666";
    private final TestRadio radio = new TestRadio();

    /** What an abstraction device is to its bus device: a listener that is also a Device, placed in a room. */
    private static final class Watcher implements BusRadioAmicaListener, Device {
        final List<byte[]> payloads = new CopyOnWriteArrayList<>();

        @Override
        public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
            payloads.add(payload);
        }

        @Override
        public String uid() {
            return "movement-uid";
        }

        @Override
        public String type() {
            return "AmicaMovement";
        }

        @Override
        public String driverUid() {
            return "d";
        }

        @Override
        public String name() {
            return "Movement 1.40";
        }

        @Override
        public DeviceStatus status() {
            return DeviceStatus.online(Instant.EPOCH);
        }

        @Override
        public List<Parameter> parameters() {
            return List.of(Parameter.writable("room", "Bathroom (room-1)", "room"));
        }

        @Override
        public void setParameter(String key, String value) {
        }

        @Override
        public List<DeviceFunction> functions() {
            return List.of();
        }

        @Override
        public String invoke(String function) {
            return "";
        }

        @Override
        public List<ConnectionInfo> connections() {
            return List.of();
        }
    }

    private void keepAliveFrom(String from, AmicaNodeType... types) {
        radio.feed(frame(1, 40, keepAlive(types)), from);
    }

    private AmicaBusDevice<String> node() {
        return radio.nodes.find(new AmicaAddress(1, 40));
    }

    private String parameter(String key) {
        return node().parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }

    private List<String> problems() {
        return radio.logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).map(EventEntry::message)
                .filter(m -> m.startsWith(NodeTypeGuard.PREFIX)).toList();
    }

    private Watcher placedMovementNode() {
        keepAliveFrom("127.0.0.1:40000", MOVEMENT);
        Watcher w = new Watcher();
        node().connect(w);
        return w;
    }

    @Test
    void aForgedKeepAliveKeepsTheTypesCountsAndReportsInPlainWords() {
        Watcher watcher = placedMovementNode();
        keepAliveFrom(FORGER, PET_COLLAR);

        assertEquals(Set.of("movement"), node().nodeTypes());
        assertEquals("movement", parameter("nodeTypes"));
        assertEquals("1", parameter("typeMismatches"));
        assertEquals("pet-collar (from route " + FORGER + ")", parameter("pendingNodeTypes"));
        assertEquals(List.of("Node type mismatch: AmICA node 1.40 is a movement node (used by 'Movement 1.40' in"
                + " Bathroom), but a keep-alive from route " + FORGER + " claims it is a pet-collar node. Nothing was"
                + " changed: the node keeps its type and its devices keep watching. This frame is not authenticated:"
                + " it may come from another program sending in the node's name. If the node really was changed (new"
                + " firmware, or another node given this address), the installer confirms with: tinysep:invoke "
                + node().uid() + " acceptNodeTypes."), problems());
        assertEquals(Integer.toString(AmicaNodeType.productId(List.of(MOVEMENT))), node().backup().state()
                .get("productId"), "the backup keeps the known product id");
        assertEquals(1, watcher.payloads.size(), "the keep-alive is still forwarded (abstraction devices ignore it)");
        assertEquals(DeviceStatus.State.ONLINE, node().status().state());

        keepAliveFrom(FORGER, PET_COLLAR);
        assertEquals("2", parameter("typeMismatches"), "every one counted");
        assertEquals(1, problems().size(), "the same claim is reported once");
        keepAliveFrom(FORGER, PET_COLLAR, DOOR);
        assertEquals(2, problems().size(), "another claim is reported too");
        assertTrue(problems().get(1).contains("claims it is a door and pet-collar node"), problems().get(1));
        assertEquals("3", radio.nodes.parameters().stream().filter(p -> p.key().equals("typeMismatches"))
                .map(Parameter::value).findFirst().orElseThrow(), "the driver's total");
    }

    @Test
    void theInstallerConfirmsARealChangeWithAnEventEntry() {
        placedMovementNode();
        keepAliveFrom(NODE.substring(6), DOOR);
        assertEquals(Set.of("movement"), node().nodeTypes());
        assertEquals(List.of("acceptNodeTypes"), node().functions().stream().map(DeviceFunction::name).toList());

        String answer = node().invoke("acceptNodeTypes");
        assertEquals("node types now [door] (were [movement]); the devices of the old types go, those of the new ones"
                + " come", answer);
        assertEquals(Set.of("door"), node().nodeTypes());
        assertEquals("", parameter("pendingNodeTypes"));
        assertEquals(Integer.toString(DOOR.bit()), node().backup().state().get("productId"));
        assertTrue(radio.logs.events().stream().anyMatch(e -> e.message().equals("node types changed from [movement]"
                + " to [door]: confirmed by the installer (acceptNodeTypes; claimed by a keep-alive from " + NODE
                + ")")), radio.logs.events().toString());
        IllegalArgumentException none = assertThrows(IllegalArgumentException.class,
                () -> node().invoke("acceptNodeTypes"));
        assertEquals("no node types are pending: the node's last keep-alive agreed with its types [door]",
                none.getMessage());
    }

    @Test
    void aKeepAliveWithTheKnownTypesWithdrawsWhatWasPending() {
        placedMovementNode();
        keepAliveFrom(FORGER, PET_COLLAR);
        keepAliveFrom("127.0.0.1:40000", MOVEMENT); // the real node again
        assertEquals("", parameter("pendingNodeTypes"));
        assertEquals("1", parameter("typeMismatches"));
        assertThrows(IllegalArgumentException.class, () -> node().invoke("acceptNodeTypes"));
        assertEquals(Set.of("movement"), node().nodeTypes());
    }

    @Test
    void withoutDependentDevicesTheChangeIsTakenAsBefore() {
        keepAliveFrom("127.0.0.1:40000", MOVEMENT);
        keepAliveFrom(FORGER, PET_COLLAR);
        assertEquals(Set.of("pet-collar"), node().nodeTypes());
        assertEquals("0", parameter("typeMismatches"));
        assertEquals(List.of(), problems());
        assertTrue(radio.logs.events().stream().anyMatch(e -> e.message().equals("node types changed from [movement]"
                + " to [pet-collar]")));
    }

    @Test
    void aListenerThatJustLeftForAnUpdateStillCountsAsDependent() {
        keepAliveFrom("127.0.0.1:40000", MOVEMENT);
        Connection c = node().connect(new Watcher());
        c.close(); // a driver being updated: its replacement is due within the handover window (10 s)
        keepAliveFrom(FORGER, PET_COLLAR);
        assertEquals(Set.of("movement"), node().nodeTypes());
        assertEquals("1", parameter("typeMismatches"));
        assertTrue(problems().get(0).contains("(used by a device that is being updated)"), problems().get(0));
    }

    @Test
    void aForgerCyclingThroughTypeSetsGetsAtMostEightReports() {
        placedMovementNode();
        AmicaNodeType[] others = {DOOR, AmicaNodeType.WINDOW, AmicaNodeType.HEATER, AmicaNodeType.SPEAKER, PET_COLLAR,
            AmicaNodeType.SIMPLE_LIGHT, AmicaNodeType.DIMMABLE_LIGHT, AmicaNodeType.PRESENCE_BED,
            AmicaNodeType.PRESENCE_SEAT, AmicaNodeType.PRESENCE_FLUSH};
        for (AmicaNodeType t : others) {
            keepAliveFrom(FORGER, t);
        }
        assertEquals(NodeTypeGuard.MAX_REPORTS, problems().size());
        assertTrue(problems().get(7).endsWith("Further different claims for this node are only counted"
                + " (typeMismatches)."), problems().get(7));
        assertEquals("10", parameter("typeMismatches"));
        radio.feed(frame(1, 40, AmicaPayloads.encode(new MotionDetection(true))), "127.0.0.1:40000");
        assertEquals(Set.of("movement"), node().nodeTypes());
    }
}
