package org.tinysep.api.sensor;

import java.util.OptionalDouble;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A temperature sensor (thesis A.10 ITemperature). */
@ProviderType
public interface TemperatureProvider extends Provider<TemperatureListener> {

    /** @return the last temperature in degrees Celsius, empty before the first report */
    OptionalDouble celsius();
}
