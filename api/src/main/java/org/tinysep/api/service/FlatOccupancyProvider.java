package org.tinysep.api.service;

import java.time.Instant;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** Whether the flat is occupied (thesis A.12 IFlatOccupancy). */
@ProviderType
public interface FlatOccupancyProvider extends Provider<FlatOccupancyListener> {

    Occupancy occupancy();

    /** @return when the current occupancy was entered */
    Instant since();
}
