package org.tinysep.api.service;

import java.time.Instant;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** The platform's clock (thesis A.15 ITimeController). Consumers read time here when it is present. */
@ProviderType
public interface TimeControllerProvider extends Provider<TimeControllerListener> {

    Instant now();

    ClockMode mode();
}
