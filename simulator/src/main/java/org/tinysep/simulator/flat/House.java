package org.tinysep.simulator.flat;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.tinysep.house.codec.HouseRoom;
import org.tinysep.house.codec.HouseXml;
import org.tinysep.house.codec.HouseXmlException;

/** The house graph: rooms by name (case-insensitive), their neighbours (symmetric) and shortest walks. */
public final class House {

    private final Map<String, Room> byKey = new LinkedHashMap<>();
    private final Map<String, Room> byUid = new HashMap<>();
    private final Map<String, List<String>> neighbours = new HashMap<>();

    /**
     * Reads a House Information file (thesis Figure 3.7) with the platform's house codec
     * ({@code org.tinysep.house.codec}, copied into the simulator's jar).
     *
     * @throws IllegalArgumentException naming {@code source} (with line and column for bad XML) and the problem
     */
    public static House read(InputStream in, String source) throws IOException {
        List<Room> rooms = new ArrayList<>();
        try {
            int n = 0;
            for (HouseRoom r : HouseXml.read(in, source).rooms()) {
                n++;
                for (String[] field : new String[][] {{"UID", r.uid()}, {"NAME", r.name()}, {"TYPE", r.type()}}) {
                    if (field[1].isEmpty()) {
                        throw new IllegalArgumentException(source + ": ROOM #" + n + " has no " + field[0]);
                    }
                }
                rooms.add(new Room(r.uid(), r.name(), r.type(), r.neighbours()));
            }
        } catch (HouseXmlException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        try {
            return new House(rooms);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(source + ": " + e.getMessage(), e);
        }
    }

    /** @throws IllegalArgumentException for duplicate UIDs or names or a neighbour UID that names no room */
    public House(List<Room> rooms) {
        for (Room r : rooms) {
            if (byUid.put(r.uid(), r) != null) {
                throw new IllegalArgumentException("duplicate room UID " + r.uid());
            }
            if (byKey.put(key(r.name()), r) != null) {
                throw new IllegalArgumentException("duplicate room name '" + r.name() + "'");
            }
            neighbours.put(r.name(), new ArrayList<>());
        }
        for (Room r : rooms) {
            for (String uid : r.neighbourUids()) {
                Room other = byUid.get(uid);
                if (other == null) {
                    throw new IllegalArgumentException("room '" + r.name() + "' names unknown neighbour " + uid);
                }
                link(r.name(), other.name());
                link(other.name(), r.name());
            }
        }
    }

    private void link(String a, String b) {
        List<String> list = neighbours.get(a);
        if (!a.equals(b) && !list.contains(b)) {
            list.add(b);
        }
    }

    private static String key(String name) {
        return name.trim().toLowerCase(Locale.ROOT);
    }

    /** @return the rooms in file order */
    public List<Room> rooms() {
        return List.copyOf(byKey.values());
    }

    /** @return the room's exact name for a case-insensitive name */
    public Optional<String> roomName(String name) {
        return Optional.ofNullable(byKey.get(key(name))).map(Room::name);
    }

    public List<String> neighbours(String room) {
        return Collections.unmodifiableList(neighbours.getOrDefault(room, List.of()));
    }

    /** @return the rooms walked through after {@code from}, ending with {@code to}; empty if equal or unreachable */
    public List<String> path(String from, String to) {
        if (from.equals(to)) {
            return List.of();
        }
        Map<String, String> previous = new HashMap<>();
        Deque<String> queue = new ArrayDeque<>(List.of(from));
        previous.put(from, from);
        while (!queue.isEmpty()) {
            String r = queue.poll();
            for (String n : neighbours(r)) {
                if (previous.putIfAbsent(n, r) == null) {
                    if (n.equals(to)) {
                        List<String> walk = new ArrayList<>();
                        for (String s = to; !s.equals(from); s = previous.get(s)) {
                            walk.add(0, s);
                        }
                        return walk;
                    }
                    queue.add(n);
                }
            }
        }
        return List.of(to);
    }
}
