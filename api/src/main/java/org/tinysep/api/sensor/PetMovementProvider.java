package org.tinysep.api.sensor;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/**
 * A pet collar's movement sensor (the thesis's IPetMovement). Deliberately a separate interface from
 * {@link MovementProvider}: a pet moving must not count as a person moving.
 */
@ProviderType
public interface PetMovementProvider extends Provider<PetMovementListener> {

    Optional<MovementEvent> lastMovement();
}
