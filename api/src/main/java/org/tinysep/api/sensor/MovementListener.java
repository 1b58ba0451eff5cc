package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives movement reports (thesis A.3 IMovementListener). */
@ConsumerType
public interface MovementListener {

    /** Called for every movement report, motion or not. */
    void movementReported(MovementProvider source, MovementEvent movement);

    /** Called when the user re-classifies the sensor as inside or outside. */
    default void locationChanged(MovementProvider source, MovementLocation location, Instant at) {
    }
}
