package org.tinysep.api.service;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** Detects that the person may have collapsed (thesis A.16 IInactivityRecognition). */
@ProviderType
public interface InactivityRecognitionProvider extends Provider<InactivityRecognitionListener> {

    InactivityState state();

    /** @return the current alert while {@link #state()} is {@link InactivityState#ALERT} */
    Optional<InactivityAlert> alert();
}
