package org.tinysep.api.actuator;

import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A dimmable light (thesis A.7 IDimmableLight): its {@link #level()} is the brightness. */
@ProviderType
public interface DimmableLightProvider extends Provider<DimmableLightListener>, PercentActuator {
}
