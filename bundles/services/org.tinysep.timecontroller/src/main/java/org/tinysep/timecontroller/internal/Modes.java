package org.tinysep.timecontroller.internal;

import java.util.Arrays;
import java.util.Locale;
import org.tinysep.api.service.ClockMode;

/** Parses a clock mode as a user types it. */
final class Modes {

    private Modes() {
    }

    /** @throws IllegalArgumentException with the accepted values, for anything but REAL or EXTERNAL (any case) */
    static ClockMode parse(String text) {
        String t = text == null ? "" : text.strip().toUpperCase(Locale.ROOT);
        try {
            return ClockMode.valueOf(t);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("unknown clock mode '" + text + "'; use one of "
                    + Arrays.toString(ClockMode.values()).toLowerCase(Locale.ROOT));
        }
    }
}
