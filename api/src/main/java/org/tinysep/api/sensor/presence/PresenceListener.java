package org.tinysep.api.sensor.presence;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives presence changes. */
@ConsumerType
public interface PresenceListener {

    /**
     * Called when the sensor turns ON or OFF, and once for its first report after it (or the platform) started:
     * {@code first} is then true, and the report tells the resting state, not a change.
     */
    void presenceChanged(PresenceProvider source, boolean present, boolean first, Instant at);
}
