package org.tinysep.api.health;

import java.time.Instant;
import java.util.List;
import java.util.Objects;

/**
 * A room none of whose sensing nodes (movement, door, window) can currently be heard.
 *
 * @param roomUid      the room
 * @param roomName     its name
 * @param since        since when no sensing node of the room has been heard (the latest of their last frames)
 * @param deviceUids   the silent bus devices of the room
 */
public record UnmonitoredRoom(String roomUid, String roomName, Instant since, List<String> deviceUids) {

    public UnmonitoredRoom {
        Objects.requireNonNull(roomUid, "roomUid");
        Objects.requireNonNull(roomName, "roomName");
        deviceUids = List.copyOf(deviceUids);
    }
}
