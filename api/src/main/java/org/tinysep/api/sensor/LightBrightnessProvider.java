package org.tinysep.api.sensor;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A light (brightness) sensor without actuator (thesis A.11 ILightBrightness). */
@ProviderType
public interface LightBrightnessProvider extends Provider<LightBrightnessListener> {

    /** @return the last measured brightness, empty before the first report */
    Optional<Percent> brightness();
}
