package org.tinysep.api.sensor;

import org.osgi.annotation.versioning.ConsumerType;

/** Receives pet movement reports. */
@ConsumerType
public interface PetMovementListener {

    void petMovementReported(PetMovementProvider source, MovementEvent movement);
}
