package org.tinysep.api.actuator;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;
import org.tinysep.api.sensor.Percent;

@ConsumerType
public interface DimmableLightListener {

    void brightnessChanged(DimmableLightProvider source, Percent brightness, Instant at);
}
