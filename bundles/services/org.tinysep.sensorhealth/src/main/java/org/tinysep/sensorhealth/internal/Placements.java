package org.tinysep.sensorhealth.internal;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * Where each node is and what it is called, kept as devices come, change and go (not rebuilt each second): the
 * devices on nodes by node address, and which node addresses changed since they were last asked about. A node is
 * placed by its bus device's own room or, more often, by the room of the device above it (the movement sensor the
 * user put in the Bathroom is connected to the node's bus device), and named by that device. Not thread-safe: the
 * platform tick is its only user.
 */
final class Placements {

    /** A device on a node: its UID, node address and room (service properties), its name and connections. */
    record OnNode(String uid, String address, String room, Supplier<String> name, Predicate<String> connectedTo) {
    }

    /** A node's name and room UID (null when unplaced). */
    record Placement(String name, String roomUid) {
    }

    private final Map<String, OnNode> byUid = new HashMap<>();
    private final Map<String, Map<String, OnNode>> byAddress = new HashMap<>();

    /**
     * A device on a node appeared or changed. @return the node addresses whose placement may have changed
     */
    String[] put(OnNode d) {
        OnNode old = byUid.put(d.uid(), d);
        if (old != null) {
            remove(old);
        }
        byAddress.computeIfAbsent(d.address(), a -> new LinkedHashMap<>()).put(d.uid(), d);
        return old == null || old.address().equals(d.address()) ? new String[] {d.address()}
                : new String[] {d.address(), old.address()};
    }

    /** A device on a node went. @return its node address, or null when it was not known */
    String remove(String uid) {
        OnNode old = byUid.remove(uid);
        if (old == null) {
            return null;
        }
        remove(old);
        return old.address();
    }

    private void remove(OnNode old) {
        Map<String, OnNode> at = byAddress.get(old.address());
        if (at != null) {
            at.remove(old.uid());
            if (at.isEmpty()) {
                byAddress.remove(old.address());
            }
        }
    }

    /**
     * @param busUid  the bus device's UID
     * @param address its node address
     * @param ownRoom the bus device's own room, null when it is not placed
     * @return the node's name and room: looks only at the devices on that node address
     */
    Placement place(String busUid, String address, String ownRoom) {
        OnNode bus = byUid.get(busUid);
        String room = ownRoom;
        String name = bus == null ? "node " + address : name(bus, "node " + address);
        for (OnNode above : byAddress.getOrDefault(address, Map.of()).values()) {
            if (!above.uid().equals(busUid) && connected(above, busUid)) {
                name = name(above, name);
                if (room == null && above.room() != null) {
                    room = above.room();
                }
                if (above.room() != null) {
                    break;
                }
            }
        }
        return new Placement(name, room);
    }

    private static String name(OnNode d, String otherwise) {
        try {
            return Objects.requireNonNullElse(d.name().get(), otherwise);
        } catch (RuntimeException e) { // a device being removed
            return otherwise;
        }
    }

    private static boolean connected(OnNode d, String busUid) {
        try {
            return d.connectedTo().test(busUid);
        } catch (RuntimeException e) {
            return false;
        }
    }
}
