package org.tinysep.api.sensor;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A movement sensor (thesis A.3 IMovement). */
@ProviderType
public interface MovementProvider extends Provider<MovementListener> {

    /** @return the last report, empty before the first */
    Optional<MovementEvent> lastMovement();

    /** @return whether the sensor watches inside or outside the house */
    MovementLocation location();
}
