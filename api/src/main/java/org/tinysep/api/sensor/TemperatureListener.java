package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives temperature reports (thesis A.10). */
@ConsumerType
public interface TemperatureListener {

    void temperatureChanged(TemperatureProvider source, double celsius, Instant at);
}
