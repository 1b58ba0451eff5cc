package org.tinysep.device.support.rooms;

import java.util.Optional;

/**
 * Where devices are and what they are called: the {@code tinysep.room} service property and the name of each
 * device, read at the moment an event arrives (the user may move a device at run time).
 */
public interface Placements {

    /** @return the UID of the room the device is placed in, empty if not placed (or unknown) */
    Optional<String> roomOf(String deviceUid);

    /** @return the device's name for people, or its UID when the device is not known */
    String nameOf(String deviceUid);
}
