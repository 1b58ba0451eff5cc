package org.tinysep.api.service;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

@ConsumerType
public interface FlatOccupancyListener {

    /** Called when the occupancy changes. */
    void occupancyChanged(FlatOccupancyProvider source, Occupancy occupancy, Instant at);
}
