package org.tinysep.api.sensor;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives brightness measurements (thesis A.11). */
@ConsumerType
public interface LightBrightnessListener {

    void brightnessChanged(LightBrightnessProvider source, Percent brightness, Instant at);
}
