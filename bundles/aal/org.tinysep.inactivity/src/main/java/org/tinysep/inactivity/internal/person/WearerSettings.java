package org.tinysep.inactivity.internal.person;

import java.time.Duration;
import java.util.Objects;

/**
 * How a person node's movement and the room sensors are told apart (bundle README, "Activity per person").
 *
 * @param movingAboveMg a movement summary whose magnitude spread is above this is movement (milli-g)
 * @param movingWithin  a node whose last movement is at most this old is moving at the moment of a room activity
 * @param notWornAfter  a node still this long while room activity nobody else explains goes on seems not worn
 */
public record WearerSettings(int movingAboveMg, Duration movingWithin, Duration notWornAfter) {

    public WearerSettings {
        Objects.requireNonNull(movingWithin, "movingWithin");
        Objects.requireNonNull(notWornAfter, "notWornAfter");
        if (movingAboveMg < 0) {
            throw new IllegalArgumentException("the movement threshold must not be negative, was " + movingAboveMg
                    + " mg");
        }
        if (movingWithin.isNegative() || movingWithin.isZero() || notWornAfter.isNegative()
                || notWornAfter.isZero()) {
            throw new IllegalArgumentException("the moving window (" + movingWithin + ") and the not-worn time ("
                    + notWornAfter + ") must be positive");
        }
    }

    /** @return 30 mg, 5 s, 2 h (the configuration's defaults) */
    public static WearerSettings defaults() {
        return new WearerSettings(30, Duration.ofSeconds(5), Duration.ofHours(2));
    }
}
