package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/**
 * Receives window changes (thesis A.4). Devices call {@link #windowChanged(WindowProvider, OpenState, boolean,
 * Instant)} (since 1.1); a listener that only implements the three-argument method hears every call as in 1.0.
 */
@ConsumerType
public interface WindowListener {

    /**
     * Called when the window's state changes (not for repeated identical reports), and once for its first report
     * after the window device started (then {@code state} is the window's resting state, not a change).
     */
    void windowChanged(WindowProvider source, OpenState state, Instant at);

    /**
     * The same call, saying what it is (since 1.1): {@code first} is true for the window's first report after its
     * device started; that report establishes the state, it is not a change (nobody touched the window). Every
     * later call is a change. The default passes the call on to
     * {@link #windowChanged(WindowProvider, OpenState, Instant)}.
     */
    default void windowChanged(WindowProvider source, OpenState state, boolean first, Instant at) {
        windowChanged(source, state, at);
    }

    /** Called when the user moves the window's configured position. */
    default void windowPositionChanged(WindowProvider source, Coordinates position, Instant at) {
    }
}
