package org.tinysep.sensorhealth.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Function;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.sensorhealth.internal.Notices.Notice;
import org.tinysep.sensorhealth.internal.Placements.OnNode;
import org.tinysep.sensorhealth.internal.Placements.Placement;

/**
 * Every node's health with where it is, kept as an index updated on change (rebuilding and sorting the
 * whole list every second took a quarter of the CPU while 10,000 devices were created). Service events only queue
 * a change; each platform second {@link #tick} applies them, asks each node for its online and battery flags (one
 * call, no allocation: {@code NodeHealthSource} has no change notification), reads the health of a node only when
 * they changed (or the source cannot tell) and does further work only for the nodes whose online or battery state
 * or placement changed: their rooms, their notices. The sorted list of all sensors is built only when asked for
 * ({@link #sensors()}), with each node's health read then. {@link #tick} runs on the platform tick's thread only.
 */
final class NodeIndex {

    /** How many ticks a changed node address is placed again (a device connects just after it registers). */
    static final int SETTLE_TICKS = 5;

    static final Comparator<SensorHealth> ORDER = Comparator
            .comparing((SensorHealth s) -> s.roomName() == null ? "\uffff" : s.roomName())
            .thenComparing(s -> s.node().nodeAddress());

    /** One bus device's node. */
    private static final class Entry {
        final String uid;
        final String address;
        final NodeHealthSource source;
        volatile String ownRoom;
        volatile Placement placement;
        volatile NodeHealth last;
        int flags = -1;
        boolean counted;
        boolean offline;

        Entry(String uid, String address, String ownRoom, NodeHealthSource source) {
            this.uid = uid;
            this.address = address;
            this.ownRoom = ownRoom;
            this.source = source;
            this.placement = new Placement("node " + address, ownRoom);
        }
    }

    /** What changed in one tick: rooms and the notices due, in the sensor list's order. */
    record Changes(RoomWatch.Changes rooms, List<Notice> notices) {
    }

    private final Queue<Runnable> pending = new ConcurrentLinkedQueue<>();
    private final Map<String, Entry> entries = new ConcurrentHashMap<>();
    private final Map<String, Set<String>> busByAddress = new HashMap<>();
    private final Map<String, Integer> unsettled = new HashMap<>();
    private final Placements placements = new Placements();
    private final RoomWatch rooms = new RoomWatch();
    private final Notices notices;
    private final Function<String, String> roomName;
    private volatile Runnable onQueued = () -> { };
    private volatile int known;
    private volatile int offline;
    private long work;
    private long reads;

    /** @param roomName a room's current name from its UID (the UID itself when the house does not know it) */
    NodeIndex(Notices notices, Function<String, String> roomName) {
        this.notices = notices;
        this.roomName = roomName;
    }

    // ---- service events (any thread): queued, applied by the next tick

    void sourceAdded(String uid, String address, String room, NodeHealthSource source) {
        queue(() -> {
            Entry old = entries.put(uid, new Entry(uid, address, room, source));
            if (old != null) {
                drop(old);
            }
            busByAddress.computeIfAbsent(address, a -> new LinkedHashSet<>()).add(uid);
            unsettled.put(address, SETTLE_TICKS);
        });
    }

    void sourceModified(String uid, String room) {
        queue(() -> {
            Entry e = entries.get(uid);
            if (e != null) {
                e.ownRoom = room;
                unsettled.put(e.address, SETTLE_TICKS);
            }
        });
    }

    void sourceRemoved(String uid, NodeHealthSource source) {
        queue(() -> {
            Entry e = entries.get(uid);
            if (e != null && e.source == source) {
                entries.remove(uid);
                drop(e);
            }
        });
    }

    void deviceChanged(OnNode d) {
        queue(() -> {
            for (String a : placements.put(d)) {
                unsettled.put(a, SETTLE_TICKS);
            }
        });
    }

    void deviceRemoved(String uid) {
        queue(() -> {
            String a = placements.remove(uid);
            if (a != null) {
                unsettled.put(a, SETTLE_TICKS);
            }
        });
    }

    private void queue(Runnable change) {
        pending.add(change);
        onQueued.run();
    }

    /** Where a queued service event says that the next tick has work (the driver's ticker). */
    void whenQueued(Runnable hook) {
        onQueued = hook;
    }

    /**
     * @return when {@link #tick} is next needed: every tick while a node is known (its online and battery flags have
     *         no change notification, so each tick asks for them) or a change waits; null while there is none (a
     *         queued service event then wakes the ticker)
     */
    Instant nextDue(Instant now) {
        return entries.isEmpty() && pending.isEmpty() && unsettled.isEmpty() ? null : now;
    }

    private void drop(Entry e) {
        Set<String> at = busByAddress.get(e.address);
        Entry now = entries.get(e.uid);
        if (at != null && (now == null || !now.address.equals(e.address))) {
            at.remove(e.uid);
            if (at.isEmpty()) {
                busByAddress.remove(e.address);
            }
        }
        if (e.counted) {
            known--;
            offline -= e.offline ? 1 : 0;
        }
        rooms.remove(e.uid);
        notices.forget(e.uid);
    }

    // ---- the platform tick

    /** One platform second: applies the queued service events, reads each node's health, handles what changed. */
    Changes tick(Instant now) {
        for (Runnable r; (r = pending.poll()) != null;) {
            r.run();
        }
        Set<Entry> changed = new LinkedHashSet<>();
        place(changed);
        for (Entry e : entries.values()) {
            NodeHealth h;
            try {
                int flags = e.source.healthFlags();
                if (flags >= 0 && flags == e.flags && e.last != null) {
                    continue; // online and battery as last read: nothing to look at
                }
                h = e.source.health();
                e.flags = flags;
                reads++;
            } catch (RuntimeException ex) { // a bus device being removed: its last state stays
                continue;
            }
            NodeHealth old = e.last;
            e.last = h;
            if (old == null || old.online() != h.online() || old.batteryLow() != h.batteryLow()) {
                changed.add(e);
            }
        }
        List<Notice> due = new ArrayList<>();
        for (Entry e : changed) {
            if (e.last == null) {
                continue; // placed, not yet read
            }
            work++;
            SensorHealth s = sensor(e);
            boolean off = !s.node().online();
            if (!e.counted) {
                e.counted = true;
                known++;
                offline += off ? 1 : 0;
            } else if (e.offline != off) {
                offline += off ? 1 : -1;
            }
            e.offline = off;
            rooms.update(e.uid, Unmonitored.sensing(s) ? s.roomUid() : null, s);
            notices.update(s, now, due);
        }
        RoomWatch.Changes r = rooms.evaluate();
        long looked = notices.looked();
        due.addAll(notices.due(now));
        work += notices.looked() - looked;
        due.sort(Comparator.comparing(Notice::sensor, ORDER));
        return new Changes(r, due);
    }

    /** Places again the nodes whose address had a device added, changed or removed in the last ticks. */
    private void place(Set<Entry> changed) {
        for (Iterator<Map.Entry<String, Integer>> i = unsettled.entrySet().iterator(); i.hasNext();) {
            Map.Entry<String, Integer> a = i.next();
            for (String uid : busByAddress.getOrDefault(a.getKey(), Set.of())) {
                Entry e = entries.get(uid);
                if (e == null) {
                    continue;
                }
                work++;
                Placement p = placements.place(uid, e.address, e.ownRoom);
                if (!p.equals(e.placement)) {
                    e.placement = p;
                    changed.add(e);
                }
            }
            if (a.getValue() <= 1) {
                i.remove();
            } else {
                a.setValue(a.getValue() - 1);
            }
        }
    }

    private SensorHealth sensor(Entry e) {
        Placement p = e.placement;
        return new SensorHealth(e.last, p.name(), p.roomUid(), p.roomUid() == null ? null : roomName.apply(p.roomUid()));
    }

    // ---- readers (any thread)

    /**
     * @return every node's health read now (the last tick's for a node that cannot be read), placed as of the last
     *         tick, by room name then node address (built on each call)
     */
    List<SensorHealth> sensors() {
        List<SensorHealth> out = new ArrayList<>();
        for (Entry e : entries.values()) {
            NodeHealth last = e.last;
            if (last != null) {
                Placement p = e.placement;
                out.add(new SensorHealth(fresh(e, last), p.name(), p.roomUid(),
                        p.roomUid() == null ? null : roomName.apply(p.roomUid())));
            }
        }
        out.sort(ORDER);
        return out;
    }

    private static NodeHealth fresh(Entry e, NodeHealth last) {
        try {
            return e.source.health();
        } catch (RuntimeException ex) { // a bus device being removed: its last state stays
            return last;
        }
    }

    RoomWatch rooms() {
        return rooms;
    }

    int known() {
        return known;
    }

    int offline() {
        return offline;
    }

    /** @return placements resolved + changed sensors handled + rooms looked at + silences checked, since start */
    long work() {
        return work + rooms.evaluated();
    }

    /** @return health reads by the ticks since start (one per node whose online or battery flags changed) */
    long reads() {
        return reads;
    }
}
