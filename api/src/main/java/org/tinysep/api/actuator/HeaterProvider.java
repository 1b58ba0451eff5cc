package org.tinysep.api.actuator;

import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A heater (thesis A.8 IHeater), with the potency actuator the AmICA heater node offers as its {@link #level()}. */
@ProviderType
public interface HeaterProvider extends Provider<HeaterListener>, PercentActuator {
}
