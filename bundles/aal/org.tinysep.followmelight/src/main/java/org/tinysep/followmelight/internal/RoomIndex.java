package org.tinysep.followmelight.internal;

import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The lights of each room, each room's in the order the lights were connected: which lights a room has is one map
 * read, whatever the number of lights in the flat. Kept up to date by its owner when a light comes, goes or moves.
 * Not thread-safe: {@link Lights} serialises calls.
 */
final class RoomIndex {

    private final Map<String, String> roomOf = new HashMap<>();
    private final Map<String, Long> order = new HashMap<>();
    private final Map<String, TreeMap<Long, String>> inRoom = new HashMap<>();
    private long next;

    /** Files light {@code uid} under {@code roomUid} (null: not placed), out of the room it was in before. */
    void place(String uid, String roomUid) {
        Long seq = order.computeIfAbsent(uid, u -> next++);
        String was = roomUid == null ? roomOf.remove(uid) : roomOf.put(uid, roomUid);
        if (was != null && !was.equals(roomUid)) {
            TreeMap<Long, String> old = inRoom.get(was);
            old.remove(seq);
            if (old.isEmpty()) {
                inRoom.remove(was);
            }
        }
        if (roomUid != null) {
            inRoom.computeIfAbsent(roomUid, r -> new TreeMap<>()).put(seq, uid);
        }
    }

    /** Forgets light {@code uid}; connected again, it counts as connected last. */
    void remove(String uid) {
        place(uid, null);
        order.remove(uid);
    }

    /** @return the UIDs of the lights in the room, in the order they were connected */
    Collection<String> in(String roomUid) {
        TreeMap<Long, String> lights = inRoom.get(roomUid);
        return lights == null ? List.of() : lights.values();
    }

    /** @return the room light {@code uid} is filed under, or null */
    String roomOf(String uid) {
        return roomOf.get(uid);
    }
}
