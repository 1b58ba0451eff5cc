package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives door changes. */
@ConsumerType
public interface DoorListener {

    /** Called when the door's state changes (not for repeated identical reports). */
    void doorChanged(DoorProvider source, OpenState state, Instant at);
}
