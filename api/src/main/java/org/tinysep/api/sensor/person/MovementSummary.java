package org.tinysep.api.sensor.person;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;

/**
 * What the person node measured over its last summary period: the mean vector (posture: which way gravity points),
 * how much the magnitude varied (movement) and its highest value (impacts).
 *
 * @param end             when the period ended (when the report was received)
 * @param span            the period's length
 * @param mean            mean acceleration over the period
 * @param magnitudeSdMg   standard deviation of the magnitude over the period, milli-g (about 0 when still)
 * @param peakMg          highest magnitude in the period, milli-g (clipped to the node's range)
 */
public record MovementSummary(Instant end, Duration span, Acceleration mean, int magnitudeSdMg, int peakMg) {

    public MovementSummary {
        Objects.requireNonNull(end, "end");
        Objects.requireNonNull(span, "span");
        Objects.requireNonNull(mean, "mean");
        if (magnitudeSdMg < 0 || peakMg < 0) {
            throw new IllegalArgumentException("magnitude figures must not be negative");
        }
    }
}
