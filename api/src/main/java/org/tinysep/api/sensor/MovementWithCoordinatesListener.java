package org.tinysep.api.sensor;

import org.osgi.annotation.versioning.ConsumerType;

/** Movement listener that also wants coordinates; called after {@link #movementReported}. */
@ConsumerType
public interface MovementWithCoordinatesListener extends MovementListener {

    void movementLocated(MovementWithCoordinatesProvider source, MovementEvent movement, Coordinates where);
}
