package org.tinysep.device.support.testing;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import org.tinysep.device.support.rooms.Placements;

/** Rooms and names kept in maps, for unit tests; a test moves a device by changing the map. */
public class FakePlacements implements Placements {

    public final Map<String, String> rooms = new HashMap<>();
    /** Names of devices; a device without one is named by its UID. */
    public final Map<String, String> names = new HashMap<>();

    @Override
    public Optional<String> roomOf(String deviceUid) {
        return Optional.ofNullable(rooms.get(deviceUid));
    }

    @Override
    public String nameOf(String deviceUid) {
        return names.getOrDefault(deviceUid, deviceUid);
    }
}
