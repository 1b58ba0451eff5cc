package org.tinysep.api.health;

import java.util.Objects;

/**
 * One node's health with where it is.
 *
 * @param node     the bus device's view of the node
 * @param name     the name shown to the user (of the bus device, or of the device placed in the room)
 * @param roomUid  the room the node is placed in, null when unplaced
 * @param roomName that room's name, null when unplaced
 */
public record SensorHealth(NodeHealth node, String name, String roomUid, String roomName) {

    public SensorHealth {
        Objects.requireNonNull(node, "node");
        Objects.requireNonNull(name, "name");
    }
}
