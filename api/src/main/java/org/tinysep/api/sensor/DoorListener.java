package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/**
 * Receives door changes. Devices call {@link #doorChanged(DoorProvider, OpenState, boolean, Instant)} (since 1.1);
 * a listener that only implements the three-argument method hears every call as in 1.0.
 */
@ConsumerType
public interface DoorListener {

    /**
     * Called when the door's state changes (not for repeated identical reports), and once for its first report after
     * the door device started (then {@code state} is the door's resting state, not a change).
     */
    void doorChanged(DoorProvider source, OpenState state, Instant at);

    /**
     * The same call, saying what it is (since 1.1): {@code first} is true for the door's first report after its
     * device started (the node powered up, the platform or the driver restarted). That report establishes the
     * state; it is not a change: a door found closed is no evidence that anybody left. Every later call is a
     * change. The default passes the call on to {@link #doorChanged(DoorProvider, OpenState, Instant)}.
     */
    default void doorChanged(DoorProvider source, OpenState state, boolean first, Instant at) {
        doorChanged(source, state, at);
    }
}
