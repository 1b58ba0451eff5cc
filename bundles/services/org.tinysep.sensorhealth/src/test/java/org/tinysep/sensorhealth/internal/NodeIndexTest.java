package org.tinysep.sensorhealth.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.sensorhealth.internal.Notices.Kind;
import org.tinysep.sensorhealth.internal.Notices.Notice;
import org.tinysep.sensorhealth.internal.Placements.OnNode;

/** The index behind Sensor Health (issue 14): work per platform second only for what changed. */
class NodeIndexTest {

    private static final Instant T0 = Instant.parse("2026-01-05T09:12:00Z");

    /** A bus device's node whose health the test sets, and the movement device placed above it. */
    private static final class Node {
        final String bus;
        final String address;
        final AtomicReference<NodeHealth> health = new AtomicReference<>();
        final AtomicBoolean connected = new AtomicBoolean(true);

        Node(int i) {
            bus = "amica-bus-" + i;
            address = "1." + i;
            set(true, T0);
        }

        void set(boolean online, Instant lastHeard) {
            health.set(new NodeHealth(bus, address, Set.of("movement"), online, lastHeard,
                    online ? null : lastHeard, Duration.ofSeconds(2), 3000, false, 10, 10, 0));
        }

        void register(NodeIndex index, String room) {
            index.sourceAdded(bus, address, null, health::get);
            index.deviceChanged(new OnNode(bus, address, null, () -> "bus " + address, b -> false));
            index.deviceChanged(new OnNode("movement-" + address, address, room, () -> "Movement " + address,
                    b -> connected.get() && b.equals(bus)));
        }
    }

    private static NodeIndex index(Duration delay) {
        return new NodeIndex(new Notices(delay), uid -> uid.replace("-uid", ""));
    }

    /** Work of {@code ticks} platform seconds, all nodes unchanged, after the start has settled. */
    private static long[] steadyAndOneChange(int nodes) {
        NodeIndex index = index(Duration.ofMinutes(10));
        List<Node> all = new ArrayList<>();
        for (int i = 0; i < nodes; i++) {
            Node n = new Node(i);
            n.register(index, (i % 7) + "-uid");
            all.add(n);
        }
        Instant t = T0;
        for (int i = 0; i <= NodeIndex.SETTLE_TICKS; i++) {
            index.tick(t = t.plusSeconds(1));
        }
        assertEquals(nodes, index.known());
        assertEquals(nodes, index.sensors().size());
        long before = index.work();
        for (int i = 0; i < 30; i++) {
            index.tick(t = t.plusSeconds(1));
        }
        long steady = index.work() - before;
        before = index.work();
        all.get(nodes / 2).set(false, t);
        index.tick(t = t.plusSeconds(1));
        long oneChange = index.work() - before;
        assertEquals(1, index.offline());
        return new long[] {steady, oneChange};
    }

    @Test
    void workPerSecondDoesNotGrowWithTheNumberOfUnchangedNodes() {
        long[] few = steadyAndOneChange(50);
        long[] many = steadyAndOneChange(10_000);
        assertEquals(0, few[0], "30 s of 50 unchanged nodes: nothing recomputed");
        assertEquals(0, many[0], "30 s of 10,000 unchanged nodes: nothing recomputed (was: every node every second)");
        assertEquals(few[1], many[1], "one node going silent costs the same among 50 or 10,000 nodes");
        assertTrue(many[1] <= 3, "one changed node, its room, its waiting silence: " + many[1]);
    }

    @Test
    void aSilentRoomIsUnmonitoredOnceAndEachNoticeIsSentOnce() {
        NodeIndex index = index(Duration.ZERO);
        Node a = new Node(1);
        Node b = new Node(2);
        Node c = new Node(3);
        a.register(index, "Bathroom-uid");
        b.register(index, "Bathroom-uid");
        c.register(index, "Kitchen-uid");
        index.tick(T0);
        a.set(false, T0);
        NodeIndex.Changes one = index.tick(T0.plusSeconds(1));
        assertEquals(List.of(), one.rooms().unmonitored(), "Bathroom still has a sensor heard");
        assertEquals(List.of(Kind.OFFLINE), one.notices().stream().map(Notice::kind).toList());
        assertEquals("Movement 1.1", one.notices().get(0).sensor().name());
        assertEquals("Bathroom", one.notices().get(0).sensor().roomName());
        b.set(false, T0.plusSeconds(5));
        NodeIndex.Changes two = index.tick(T0.plusSeconds(6));
        assertEquals(1, two.rooms().unmonitored().size());
        assertEquals("Bathroom", two.rooms().unmonitored().get(0).roomName());
        assertEquals(T0.plusSeconds(5), two.rooms().unmonitored().get(0).since());
        assertEquals(List.of("amica-bus-1", "amica-bus-2"), two.rooms().unmonitored().get(0).deviceUids());
        NodeIndex.Changes three = index.tick(T0.plusSeconds(7));
        assertEquals(List.of(), three.rooms().unmonitored(), "told once");
        assertEquals(List.of(), three.notices(), "once per silence");
        assertEquals(2, index.offline());
        b.set(true, T0.plusSeconds(8));
        NodeIndex.Changes back = index.tick(T0.plusSeconds(8));
        assertEquals(List.of("Bathroom-uid"), back.rooms().monitoredAgain().stream().map(r -> r.roomUid()).toList());
        assertEquals(List.of(Kind.BACK), back.notices().stream().map(Notice::kind).toList());
        assertTrue(index.rooms().unmonitored().isEmpty());
    }

    @Test
    void aNodeIsPlacedByTheDeviceAboveOnceThatConnectsAndListedByRoomThenAddress() {
        NodeIndex index = index(Duration.ZERO);
        Node n = new Node(9);
        n.connected.set(false); // registered, not yet connected to its bus device
        n.register(index, "Kitchen-uid");
        Node m = new Node(10);
        m.register(index, "Bathroom-uid");
        index.tick(T0);
        SensorHealth unplaced = index.sensors().get(1);
        assertEquals("bus 1.9", unplaced.name());
        assertEquals(null, unplaced.roomName(), "unplaced nodes come last");
        n.connected.set(true);
        index.tick(T0.plusSeconds(1));
        List<String> order = index.sensors().stream().map(s -> s.roomName() + " " + s.name()).toList();
        assertEquals(List.of("Bathroom Movement 1.10", "Kitchen Movement 1.9"), order);
        index.deviceRemoved("movement-1.9");
        index.sourceRemoved(n.bus, null); // not the registered source object: ignored
        index.tick(T0.plusSeconds(2));
        assertEquals("bus 1.9", index.sensors().get(1).name(), "placed by its bus device again");
        assertEquals(2, index.known());
    }

    /**
     * Issue 25, item 1: a room whose sensor device goes (removed, or its node re-typed by a forged keep-alive) while
     * none of its sensors is heard is not "monitored again": it stays unmonitored until a sensor placed there
     * reports; a room removed from the house is forgotten.
     */
    @Test
    void anUnmonitoredRoomWhoseSensorDeviceGoesStaysUnmonitored() {
        NodeIndex index = index(Duration.ZERO);
        Node a = new Node(1);
        a.register(index, "Bathroom-uid");
        index.tick(T0);
        a.set(false, T0);
        NodeIndex.Changes silent = index.tick(T0.plusSeconds(1));
        assertEquals(List.of("Bathroom-uid"), silent.rooms().unmonitored().stream().map(r -> r.roomUid()).toList());

        index.deviceRemoved("movement-" + a.address);
        NodeIndex.Changes gone = index.tick(T0.plusSeconds(2));
        assertEquals(List.of(), gone.rooms().monitoredAgain(), "a sensor that went is no sensor heard again");
        assertEquals(List.of("Bathroom-uid"), gone.rooms().sensorGone().stream().map(r -> r.roomUid()).toList());
        assertEquals(List.of("Bathroom-uid"), index.rooms().unmonitored().stream().map(r -> r.roomUid()).toList());
        assertEquals(List.of(), index.tick(T0.plusSeconds(3)).rooms().sensorGone(), "told once");

        a.set(true, T0.plusSeconds(4)); // the sensor is placed there again and reports
        index.deviceChanged(new OnNode("movement-" + a.address, a.address, "Bathroom-uid", () -> "Movement",
                b -> b.equals(a.bus)));
        NodeIndex.Changes back = index.tick(T0.plusSeconds(4));
        assertEquals(List.of("Bathroom-uid"), back.rooms().monitoredAgain().stream().map(r -> r.roomUid()).toList());
        assertTrue(index.rooms().unmonitored().isEmpty());
    }

    @Test
    void anUnmonitoredRoomWithoutSensorThatLeftTheHouseIsForgotten() {
        NodeIndex index = index(Duration.ZERO);
        Node a = new Node(1);
        a.register(index, "Bathroom-uid");
        index.tick(T0);
        a.set(false, T0);
        index.tick(T0.plusSeconds(1));
        index.deviceRemoved("movement-" + a.address);
        index.tick(T0.plusSeconds(2));
        index.rooms().dropRemovedRooms(r -> r.equals("Bathroom-uid"));
        assertTrue(index.rooms().unmonitored().isEmpty());
    }

    /**
     * Issue 29 (idle CPU): a bus device that tells its online and battery flags (NodeHealthSource.healthFlags) is not
     * read on a tick where they are unchanged; the one that changed is read and counted, and the sensor list still
     * shows each node's health as it is now.
     */
    @Test
    void anIdleTickReadsNoNodeWhoseFlagsAreUnchanged() {
        NodeIndex index = index(Duration.ofMinutes(10));
        List<Node> all = new ArrayList<>();
        int[] healthReads = {0};
        for (int i = 0; i < 50; i++) {
            Node n = new Node(i);
            index.sourceAdded(n.bus, n.address, "room-uid", new NodeHealthSource() {
                @Override
                public NodeHealth health() {
                    healthReads[0]++;
                    return n.health.get();
                }

                @Override
                public int healthFlags() {
                    NodeHealth h = n.health.get();
                    return (h.online() ? 1 : 0) | (h.batteryLow() ? 2 : 0);
                }
            });
            all.add(n);
        }
        Instant t = T0;
        for (int i = 0; i <= NodeIndex.SETTLE_TICKS; i++) {
            index.tick(t = t.plusSeconds(1));
        }
        assertEquals(50, index.known());
        int before = healthReads[0];
        long readsBefore = index.reads();
        for (int i = 0; i < 60; i++) {
            all.get(i % 50).set(true, t); // heard again: online as before
            index.tick(t = t.plusSeconds(1));
        }
        assertEquals(0, healthReads[0] - before, "a minute of ticks, flags unchanged: health reads");
        all.get(7).set(false, t);
        index.tick(t = t.plusSeconds(1));
        assertEquals(1, index.reads() - readsBefore, "the node whose flags changed is read");
        assertEquals(1, index.offline());
        Instant heard = t;
        all.get(9).set(true, heard);
        assertEquals(heard, index.sensors().stream().filter(s -> s.node().nodeAddress().equals("1.9")).findFirst()
                .orElseThrow().node().lastHeard(), "the sensor list reads each node when asked");
    }

    /** Issue 29, idle: without nodes the ticker need not call Sensor Health; a node coming wakes it. */
    @Test
    void withoutNodesNoTickIsNeededAndANodeComingWakesTheTicker() {
        NodeIndex index = index(Duration.ofMinutes(10));
        int[] woken = {0};
        index.whenQueued(() -> woken[0]++);
        index.tick(T0);
        assertEquals(null, index.nextDue(T0), "no node, nothing queued: no tick needed");
        Node n = new Node(1);
        n.register(index, "kitchen");
        assertTrue(woken[0] > 0, "a node registered wakes the ticker");
        assertEquals(T0, index.nextDue(T0), "queued: the next tick applies it");
        index.tick(T0.plusSeconds(1));
        assertEquals(T0.plusSeconds(1), index.nextDue(T0.plusSeconds(1)), "a known node's flags are asked each tick");
    }
}
