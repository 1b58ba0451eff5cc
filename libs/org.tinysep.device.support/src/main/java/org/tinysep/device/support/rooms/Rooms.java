package org.tinysep.device.support.rooms;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import org.tinysep.api.service.Room;

/**
 * Finds a room the way a user names it: its UID, a unique UID prefix of at least {@value #MIN_PREFIX} characters,
 * or its exact name (case-insensitive). Used by the {@code room} device parameter and the house shell commands.
 */
public final class Rooms {

    /** Shortest UID prefix accepted. */
    public static final int MIN_PREFIX = 4;

    private Rooms() {
    }

    /**
     * @return the one room {@code query} names
     * @throws IllegalArgumentException when no room or more than one matches, with the candidates
     */
    public static Room resolve(List<Room> rooms, String query) {
        String q = query == null ? "" : query.strip();
        if (q.isEmpty()) {
            throw new IllegalArgumentException("no room given");
        }
        for (Room r : rooms) {
            if (r.uid().equalsIgnoreCase(q)) {
                return r;
            }
        }
        List<Room> byName = rooms.stream().filter(r -> r.name().equalsIgnoreCase(q)).toList();
        if (byName.size() == 1) {
            return byName.get(0);
        }
        if (byName.size() > 1) {
            throw new IllegalArgumentException("room name '" + q + "' is ambiguous: " + describe(byName)
                    + "; use the UID");
        }
        String lower = q.toLowerCase(Locale.ROOT);
        List<Room> byPrefix = q.length() < MIN_PREFIX ? List.of()
                : rooms.stream().filter(r -> r.uid().toLowerCase(Locale.ROOT).startsWith(lower)).toList();
        if (byPrefix.size() == 1) {
            return byPrefix.get(0);
        }
        if (byPrefix.size() > 1) {
            throw new IllegalArgumentException("UID prefix '" + q + "' is ambiguous: " + describe(byPrefix));
        }
        throw new IllegalArgumentException("unknown room '" + q + "'; known rooms: "
                + (rooms.isEmpty() ? "none" : describe(rooms)));
    }

    /** @return {@code name (uid)} */
    public static String label(Room room) {
        return room.name() + " (" + room.uid() + ")";
    }

    private static String describe(List<Room> rooms) {
        return rooms.stream().map(Rooms::label).collect(Collectors.joining(", "));
    }
}
