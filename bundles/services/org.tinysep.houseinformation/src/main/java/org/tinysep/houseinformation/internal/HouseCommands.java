package org.tinysep.houseinformation.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.rooms.Rooms;

/**
 * What the house shell commands do, framework-free: each returns its output as text or throws
 * {@link IllegalArgumentException} with a one-line message. Room arguments are a UID, a unique UID prefix of 4+
 * characters or an exact name (case-insensitive).
 */
final class HouseCommands {

    private final HouseInformationProvider house;
    private final Supplier<Map<String, List<String>>> devicesByRoom;

    /** @param devicesByRoom room UID → names of the devices placed there */
    HouseCommands(HouseInformationProvider house, Supplier<Map<String, List<String>>> devicesByRoom) {
        this.house = house;
        this.devicesByRoom = devicesByRoom;
    }

    String rooms() {
        List<Room> rooms = house.rooms();
        if (rooms.isEmpty()) {
            return "no rooms; add one with: room-add <name> <type>";
        }
        Map<String, List<String>> devices = devicesByRoom.get();
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"UID", "NAME", "TYPE", "NEIGHBOURS", "DEVICES"});
        for (Room r : rooms) {
            String neighbours = rooms.stream().filter(o -> r.neighbours().contains(o.uid())).map(Room::name)
                    .collect(Collectors.joining(", "));
            rows.add(new String[] {r.uid(), r.name(), r.type(), neighbours,
                    String.join(", ", devices.getOrDefault(r.uid(), List.of()))});
        }
        return table(rows);
    }

    /** @param isNew whether a type that is neither standard nor used yet is meant ({@link RoomTypes#NEW_TYPE}) */
    String add(String name, String type, boolean isNew) {
        boolean fresh = RoomTypes.find(type, house.rooms()).isEmpty();
        Room added = house.addRoom(name, RoomTypes.check(type, isNew, house.rooms()));
        return "added " + Rooms.label(added) + ", type " + added.type() + (fresh ? " (a new type: Inactivity"
                + " Recognition uses its default limit for it until its typeLimits names it)" : "");
    }

    String add(String name, String type) {
        return add(name, type, false);
    }

    String rename(String room, String name, String type, boolean isNew) {
        Room r = find(room);
        Room updated = house.updateRoom(r.uid(), name, type == null ? r.type()
                : RoomTypes.check(type, isNew, house.rooms()));
        return "updated " + Rooms.label(updated) + ", type " + updated.type();
    }

    String rename(String room, String name, String type) {
        return rename(room, name, type, false);
    }

    String link(String a, String b) {
        Room ra = find(a);
        Room rb = find(b);
        house.link(ra.uid(), rb.uid());
        return "linked " + ra.name() + " <-> " + rb.name();
    }

    String unlink(String a, String b) {
        Room ra = find(a);
        Room rb = find(b);
        house.unlink(ra.uid(), rb.uid());
        return "unlinked " + ra.name() + " <-> " + rb.name();
    }

    String remove(String room) {
        Room r = find(room);
        house.removeRoom(r.uid());
        return "removed " + Rooms.label(r);
    }

    private Room find(String query) {
        return Rooms.resolve(house.rooms(), query);
    }

    private static String table(List<String[]> rows) {
        int[] width = new int[rows.get(0).length];
        for (String[] row : rows) {
            for (int i = 0; i < row.length; i++) {
                width[i] = Math.max(width[i], row[i].length());
            }
        }
        StringBuilder s = new StringBuilder();
        for (String[] row : rows) {
            StringBuilder line = new StringBuilder();
            for (int i = 0; i < row.length; i++) {
                line.append(String.format("%-" + width[i] + "s", row[i])).append(i < row.length - 1 ? "  " : "");
            }
            s.append(line.toString().stripTrailing()).append('\n');
        }
        return s.toString().stripTrailing();
    }
}
