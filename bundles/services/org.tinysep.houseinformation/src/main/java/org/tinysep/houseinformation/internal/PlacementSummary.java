package org.tinysep.houseinformation.internal;

import java.util.Set;
import java.util.TreeSet;

/**
 * Sums up a burst of room placements in one console line (a start places every node's devices at once: one line
 * each would bury the shell prompt). Not thread-safe: the placer uses it on its own thread.
 */
final class PlacementSummary {

    private final Set<String> rooms = new TreeSet<>();
    private int devices;

    /** @return true for the first placement of a burst: the caller schedules {@link #takeLine()} */
    boolean add(String room) {
        rooms.add(room);
        return ++devices == 1;
    }

    /** @return e.g. {@code Placed 44 devices in 6 rooms by their node address: Bathroom, Bedroom, …}; resets */
    String takeLine() {
        String line = "Placed " + devices + (devices == 1 ? " device" : " devices") + " in " + rooms.size()
                + (rooms.size() == 1 ? " room" : " rooms") + " by their node address: " + String.join(", ", rooms)
                + " (tinysep:rooms lists them)";
        devices = 0;
        rooms.clear();
        return line;
    }
}
