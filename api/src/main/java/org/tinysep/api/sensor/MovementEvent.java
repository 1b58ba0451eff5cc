package org.tinysep.api.sensor;

import java.time.Instant;
import java.util.Objects;

/**
 * A movement report (thesis A.3 SLastMovement): whether motion was detected, and when.
 *
 * @param detected true for motion, false for "no motion any more"
 * @param at       when the report was received
 */
public record MovementEvent(boolean detected, Instant at) {

    public MovementEvent {
        Objects.requireNonNull(at, "at");
    }
}
