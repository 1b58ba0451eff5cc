package org.tinysep.api.actuator;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

@ConsumerType
public interface SimpleLightListener {

    /** Called when the node reports a changed on/off state. */
    void lightSwitched(SimpleLightProvider source, boolean on, Instant at);
}
