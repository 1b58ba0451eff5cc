package org.tinysep.followmelight.internal;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.device.support.rooms.Placements;

/**
 * Placements kept as the platform's directory keeps them (the room per UID stored, a look-up allocates nothing),
 * counting the room look-ups: the work a report or a switching does in the directory.
 */
final class CountingPlacements implements Placements {

    private final Map<String, Optional<String>> rooms = new ConcurrentHashMap<>();
    long roomLookups;

    void place(String uid, String roomUid) {
        rooms.put(uid, Optional.ofNullable(roomUid));
    }

    @Override
    public Optional<String> roomOf(String deviceUid) {
        roomLookups++;
        return rooms.getOrDefault(deviceUid, Optional.empty());
    }

    @Override
    public String nameOf(String deviceUid) {
        return deviceUid;
    }
}
