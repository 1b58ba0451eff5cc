package org.tinysep.sensorhealth.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.UnmonitoredRoom;

/**
 * The sensing nodes of each room and the rooms that are unmonitored, kept up to date one changed sensor at a time:
 * only the rooms of sensors that changed are looked at again ({@link Unmonitored} decides). Not thread-safe: the
 * platform tick is its only writer; {@link #unmonitored()} is a snapshot for readers.
 */
final class RoomWatch {

    /**
     * Rooms that became unmonitored, rooms monitored again, and unmonitored rooms whose last sensing device went
     * (they stay unmonitored: a sensor that is gone is not a sensor heard again), in this tick.
     */
    record Changes(List<UnmonitoredRoom> unmonitored, List<UnmonitoredRoom> monitoredAgain,
            List<UnmonitoredRoom> sensorGone) {

        Changes(List<UnmonitoredRoom> unmonitored, List<UnmonitoredRoom> monitoredAgain) {
            this(unmonitored, monitoredAgain, List.of());
        }
    }

    private final Map<String, Map<String, SensorHealth>> members = new HashMap<>();
    private final Map<String, String> roomOf = new HashMap<>();
    private final Set<String> dirty = new LinkedHashSet<>();
    private final Map<String, UnmonitoredRoom> unmonitored = new LinkedHashMap<>();
    /** Unmonitored rooms with no sensing device placed there any more (already told). */
    private final Set<String> sensorless = new LinkedHashSet<>();
    private volatile List<UnmonitoredRoom> snapshot = List.of();
    private long evaluated;

    /** A sensor changed: {@code room} is its room when it is a placed sensing node, else null. */
    void update(String uid, String room, SensorHealth s) {
        String old = room == null ? roomOf.remove(uid) : roomOf.put(uid, room);
        if (old != null && !old.equals(room)) {
            leave(old, uid);
        }
        if (room != null) {
            members.computeIfAbsent(room, r -> new LinkedHashMap<>()).put(uid, s);
            dirty.add(room);
        }
    }

    /** A sensor went. */
    void remove(String uid) {
        String old = roomOf.remove(uid);
        if (old != null) {
            leave(old, uid);
        }
    }

    private void leave(String room, String uid) {
        Map<String, SensorHealth> in = members.get(room);
        if (in != null) {
            in.remove(uid);
            if (in.isEmpty()) {
                members.remove(room);
            }
        }
        dirty.add(room);
    }

    /** @return the rooms that changed state since the last call; only rooms with a changed sensor are looked at */
    Changes evaluate() {
        if (dirty.isEmpty()) {
            return new Changes(List.of(), List.of());
        }
        List<UnmonitoredRoom> became = new ArrayList<>();
        List<UnmonitoredRoom> again = new ArrayList<>();
        List<UnmonitoredRoom> gone = new ArrayList<>();
        for (String room : dirty) {
            evaluated++;
            List<SensorHealth> in = new ArrayList<>(members.getOrDefault(room, Map.of()).values());
            in.sort(Comparator.comparing(s -> s.node().nodeAddress()));
            List<UnmonitoredRoom> u = Unmonitored.of(in);
            if (u.isEmpty() && unmonitored.containsKey(room) && in.stream().noneMatch(Unmonitored::sensing)) {
                // its sensor device went (removed, re-typed), none was heard: it stays unmonitored
                if (sensorless.add(room)) {
                    gone.add(unmonitored.get(room));
                }
                continue;
            }
            sensorless.remove(room);
            if (!u.isEmpty()) {
                if (unmonitored.put(room, u.get(0)) == null) {
                    became.add(u.get(0));
                }
            } else {
                UnmonitoredRoom was = unmonitored.remove(room);
                if (was != null) {
                    again.add(was);
                }
            }
        }
        dirty.clear();
        snapshot = List.copyOf(unmonitored.values());
        became.sort(Comparator.comparing(UnmonitoredRoom::roomName));
        again.sort(Comparator.comparing(UnmonitoredRoom::roomName));
        gone.sort(Comparator.comparing(UnmonitoredRoom::roomName));
        return new Changes(became, again, gone);
    }

    /**
     * Forgets the unmonitored rooms without a sensing device that are no longer in the house (removed by the
     * user): a room that does not exist is not watched by anyone, and is no unmonitored room either.
     */
    void dropRemovedRooms(java.util.function.Predicate<String> removed) {
        List<String> drop = sensorless.stream().filter(removed).toList();
        if (drop.isEmpty()) {
            return;
        }
        drop.forEach(r -> {
            sensorless.remove(r);
            unmonitored.remove(r);
        });
        snapshot = List.copyOf(unmonitored.values());
    }

    /** @return the unmonitored rooms now (names as of their last change) */
    List<UnmonitoredRoom> unmonitored() {
        return snapshot;
    }

    /** @return how many times a room was looked at again (for tests: work per tick) */
    long evaluated() {
        return evaluated;
    }
}
