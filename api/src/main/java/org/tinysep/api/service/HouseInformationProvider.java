package org.tinysep.api.service;

import java.util.List;
import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** The house plan (thesis 3.6 / A.13 IHouseInformation). Changes are saved and announced to listeners. */
@ProviderType
public interface HouseInformationProvider extends Provider<HouseInformationListener> {

    /** @return all rooms in a stable order */
    List<Room> rooms();

    Optional<Room> room(String uid);

    /** Adds a room with a generated UID. @throws IllegalArgumentException on a blank name or type */
    Room addRoom(String name, String type);

    /** Renames or retypes a room. @throws IllegalArgumentException if unknown or blank */
    Room updateRoom(String uid, String name, String type);

    /** Links two rooms both ways. @throws IllegalArgumentException if either is unknown or they are equal */
    void link(String roomUid, String otherRoomUid);

    void unlink(String roomUid, String otherRoomUid);

    /** Removes a room and its links. @return whether it existed */
    boolean removeRoom(String uid);
}
