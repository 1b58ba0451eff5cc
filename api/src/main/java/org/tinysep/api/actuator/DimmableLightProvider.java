package org.tinysep.api.actuator;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;
import org.tinysep.api.sensor.Percent;

/** A dimmable light (thesis A.7 IDimmableLight). */
@ProviderType
public interface DimmableLightProvider extends Provider<DimmableLightListener> {

    /** @return the brightness last reported by the node; empty before its first report */
    Optional<Percent> brightness();

    /** Asks the node to change brightness; confirmed to listeners by the node's next status packet. */
    void setBrightness(Percent brightness);
}
