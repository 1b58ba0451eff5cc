package org.tinysep.device.support.sensor;

import java.util.Locale;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementLocation;

/** What person and pet movement sensors of both node families share beyond {@link SensorDevice}. */
public final class Movements {

    private Movements() {
    }

    /** @return whether {@code now} is a change from {@code before}: motion versus no motion */
    public static boolean isChange(MovementEvent before, MovementEvent now) {
        return before.detected() != now.detected();
    }

    /** @return the read-only {@code lastMovement} parameter, e.g. "motion at 2026-11-22T10:00:00Z" */
    public static Parameter lastMovement(MovementEvent e) {
        return Parameter.readOnly("lastMovement", e == null ? "" : (e.detected() ? "motion at " : "none at ") + e.at(),
                "last report");
    }

    /** @return the writable {@code location} parameter */
    public static Parameter location(MovementLocation location) {
        return Parameter.writable("location", location, "INSIDE or OUTSIDE the flat");
    }

    /** @return the location a user typed, e.g. "inside" */
    public static MovementLocation parseLocation(String value) {
        try {
            return MovementLocation.valueOf(value.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException | NullPointerException e) {
            throw new IllegalArgumentException("location must be INSIDE or OUTSIDE, was '" + value + "'");
        }
    }
}
