package org.tinysep.api.service;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

@ConsumerType
public interface TimeControllerListener {

    /** Called each time the clock advances by a step (every second in external mode). */
    void timeAdvanced(TimeControllerProvider source, Instant now);

    default void modeChanged(TimeControllerProvider source, ClockMode mode, Instant at) {
    }
}
