package org.tinysep.houseinformation.internal;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import org.tinysep.api.service.Room;

/**
 * The room types {@code room-add} accepts without asking. A room's type decides how long Inactivity Recognition
 * waits in it (its {@code typeLimits}, by type): a mistyped type ("Bathrom") would silently get the default limit,
 * so the shell refuses types it does not know unless the user says the type is new ({@code --new-type}).
 */
final class RoomTypes {

    /** The types Inactivity Recognition has a limit for by default ({@code typeLimits}), plus Study and Toilet. */
    static final List<String> STANDARD = List.of("Bathroom", "Bedroom", "Hall", "Kitchen", "Living room", "Study",
            "Toilet");
    /** The flag that accepts a type that is neither standard nor used by a room yet. */
    static final String NEW_TYPE = "--new-type";

    private RoomTypes() {
    }

    /** @return the standard types and those of the house's rooms, in that order */
    static Set<String> known(List<Room> rooms) {
        Set<String> out = new LinkedHashSet<>(STANDARD);
        rooms.forEach(r -> out.add(r.type()));
        return out;
    }

    /** @return the known type's spelling for {@code type} (compared ignoring case), if it is known */
    static Optional<String> find(String type, List<Room> rooms) {
        String t = type.strip().toLowerCase(Locale.ROOT);
        return known(rooms).stream().filter(k -> k.toLowerCase(Locale.ROOT).equals(t)).findFirst();
    }

    /**
     * @return the type to store: the known spelling, or {@code type} itself when {@code isNew}
     * @throws IllegalArgumentException for an unknown type without {@code isNew}
     */
    static String check(String type, boolean isNew, List<Room> rooms) {
        Optional<String> known = find(type, rooms);
        if (known.isPresent()) {
            return known.get();
        }
        if (isNew) {
            return type.strip();
        }
        throw new IllegalArgumentException("unknown room type '" + type.strip() + "'; known types: "
                + String.join(", ", known(rooms)) + ". Inactivity Recognition's limits go by type: a new type gets"
                + " its default limit until you add it to its typeLimits. To use it anyway, add " + NEW_TYPE);
    }
}
