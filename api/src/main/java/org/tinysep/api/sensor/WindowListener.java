package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives window changes (thesis A.4). */
@ConsumerType
public interface WindowListener {

    /** Called when the window's state changes. */
    void windowChanged(WindowProvider source, OpenState state, Instant at);

    /** Called when the user moves the window's configured position. */
    default void windowPositionChanged(WindowProvider source, Coordinates position, Instant at) {
    }
}
