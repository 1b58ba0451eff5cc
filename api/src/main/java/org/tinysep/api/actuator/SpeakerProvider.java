package org.tinysep.api.actuator;

import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A speaker (thesis A.9 ISpeaker): its {@link #level()} is the volume. */
@ProviderType
public interface SpeakerProvider extends Provider<SpeakerListener>, PercentActuator {
}
