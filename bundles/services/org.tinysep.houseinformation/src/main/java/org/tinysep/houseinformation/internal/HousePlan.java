package org.tinysep.houseinformation.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.tinysep.api.service.Room;

/**
 * An immutable, valid house plan: unique UIDs, non-blank names and types, neighbours that exist, symmetric links,
 * no room its own neighbour. Every change returns a new plan or throws {@link IllegalArgumentException}.
 */
final class HousePlan {

    static final HousePlan EMPTY = new HousePlan(new LinkedHashMap<>());

    private final Map<String, Room> rooms; // in file / creation order

    private HousePlan(Map<String, Room> rooms) {
        this.rooms = rooms;
    }

    /**
     * Checks rooms as read from a file; a link listed on one side only is completed on the other.
     *
     * @throws IllegalArgumentException naming the first problem
     */
    static HousePlan of(List<Room> list) {
        Map<String, Room> byUid = new LinkedHashMap<>();
        int n = 0;
        for (Room r : list) {
            n++;
            String where = "room #" + n + (r.uid().isBlank() ? "" : " (UID " + r.uid() + ")");
            if (r.uid().isBlank()) {
                throw new IllegalArgumentException(where + " has no UID");
            }
            requireText(r.name(), where + ": blank NAME");
            requireText(r.type(), where + ": blank TYPE");
            if (byUid.put(r.uid(), r) != null) {
                throw new IllegalArgumentException(where + ": duplicate UID " + r.uid());
            }
        }
        Map<String, Set<String>> links = new LinkedHashMap<>();
        byUid.keySet().forEach(uid -> links.put(uid, new HashSet<>()));
        for (Room r : byUid.values()) {
            for (String other : r.neighbours()) {
                if (!byUid.containsKey(other)) {
                    throw new IllegalArgumentException("room " + r.uid() + " (" + r.name() + "): unknown neighbour UID "
                            + other);
                }
                if (other.equals(r.uid())) {
                    throw new IllegalArgumentException("room " + r.uid() + " (" + r.name() + ") is its own neighbour");
                }
                links.get(r.uid()).add(other);
                links.get(other).add(r.uid());
            }
        }
        Map<String, Room> out = new LinkedHashMap<>();
        byUid.values().forEach(r -> out.put(r.uid(), new Room(r.uid(), r.name().strip(), r.type().strip(),
                links.get(r.uid()))));
        return new HousePlan(out);
    }

    static String requireText(String value, String message) {
        if (value == null || value.isBlank()) {
            throw new IllegalArgumentException(message);
        }
        return value.strip();
    }

    List<Room> rooms() {
        return List.copyOf(rooms.values());
    }

    Optional<Room> room(String uid) {
        return Optional.ofNullable(uid == null ? null : rooms.get(uid));
    }

    /** @return the neighbours of a room in plan order (stable, for the file and the shell) */
    List<String> orderedNeighbours(Room room) {
        List<String> order = new ArrayList<>(rooms.keySet());
        return room.neighbours().stream().sorted(Comparator.comparingInt(order::indexOf)).toList();
    }

    HousePlan withRoom(String uid, String name, String type) {
        Map<String, Room> next = new LinkedHashMap<>(rooms);
        Room old = rooms.get(uid);
        next.put(uid, new Room(uid, requireText(name, "room name must not be blank"),
                requireText(type, "room type must not be blank"), old == null ? Set.of() : old.neighbours()));
        return new HousePlan(next);
    }

    HousePlan linked(String a, String b, boolean link) {
        Room ra = existing(a);
        Room rb = existing(b);
        if (a.equals(b)) {
            throw new IllegalArgumentException("a room cannot be linked to itself: " + ra.name());
        }
        Map<String, Room> next = new LinkedHashMap<>(rooms);
        next.put(a, withNeighbour(ra, b, link));
        next.put(b, withNeighbour(rb, a, link));
        return new HousePlan(next);
    }

    HousePlan without(String uid) {
        existing(uid);
        Map<String, Room> next = new LinkedHashMap<>();
        for (Room r : rooms.values()) {
            if (!r.uid().equals(uid)) {
                next.put(r.uid(), withNeighbour(r, uid, false));
            }
        }
        return new HousePlan(next);
    }

    Room existing(String uid) {
        Room r = uid == null ? null : rooms.get(uid);
        if (r == null) {
            throw new IllegalArgumentException("unknown room UID '" + uid + "'");
        }
        return r;
    }

    private static Room withNeighbour(Room r, String other, boolean present) {
        Set<String> n = new LinkedHashSet<>(r.neighbours());
        if (present) {
            n.add(other);
        } else {
            n.remove(other);
        }
        return new Room(r.uid(), r.name(), r.type(), n);
    }
}
