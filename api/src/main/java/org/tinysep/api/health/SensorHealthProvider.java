package org.tinysep.api.health;

import java.util.List;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/**
 * Which nodes are silent and which rooms are therefore unmonitored: for services that must not mistake a dead
 * sensor for an inactive person (Inactivity Recognition, Flat Occupancy) and for caregivers' notices.
 */
@ProviderType
public interface SensorHealthProvider extends Provider<SensorHealthListener> {

    /** @return every known node's health, ordered by room name then node address */
    List<SensorHealth> sensors();

    /** @return the rooms whose sensing nodes are all silent now, ordered by room name */
    List<UnmonitoredRoom> unmonitoredRooms();
}
