package org.tinysep.api.health;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Told when a room becomes unmonitored or is monitored again; called on the platform tick's thread. */
@ConsumerType
public interface SensorHealthListener {

    void roomUnmonitored(SensorHealthProvider source, UnmonitoredRoom room, Instant at);

    default void roomMonitoredAgain(SensorHealthProvider source, String roomUid, Instant at) {
    }
}
