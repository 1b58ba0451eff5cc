package org.tinysep.api.sensor;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;

/**
 * A movement sensor that also knows where the motion happened (thesis 3.5 interface extension). Its devices
 * register under both this name and {@link MovementProvider}, so consumers of plain movement keep working.
 * A listener that implements {@link MovementWithCoordinatesListener} also gets the coordinates.
 */
@ProviderType
public interface MovementWithCoordinatesProvider extends MovementProvider {

    /** @return where the last motion was detected, empty if unknown */
    Optional<Coordinates> lastCoordinates();
}
