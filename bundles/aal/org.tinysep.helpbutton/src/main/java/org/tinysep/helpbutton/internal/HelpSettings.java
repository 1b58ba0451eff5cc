package org.tinysep.helpbutton.internal;

import java.time.DateTimeException;
import java.time.Duration;
import java.time.ZoneId;

/**
 * The help button's settings, checked.
 *
 * @param hold   how long a switch must be held
 * @param cancel how long after the call a second press cancels it; zero = never
 * @param button 1, 2, or 0 for either
 * @param zone   the zone of times in words
 */
record HelpSettings(Duration hold, Duration cancel, int button, ZoneId zone) {

    static final HelpSettings DEFAULTS = new HelpSettings(Duration.ofSeconds(1), Duration.ofSeconds(10), 0,
            ZoneId.systemDefault());

    /**
     * @return the settings of {@code c}
     * @throws IllegalArgumentException naming the first bad setting and its allowed range
     */
    static HelpSettings parse(HelpButtonConfig c) {
        if (c.holdMillis() < 100 || c.holdMillis() > 10_000) {
            throw new IllegalArgumentException("holdMillis " + c.holdMillis() + " is outside 100..10000");
        }
        if (c.cancelSeconds() < 0 || c.cancelSeconds() > 120) {
            throw new IllegalArgumentException("cancelSeconds " + c.cancelSeconds() + " is outside 0..120");
        }
        if (c.button() < 0 || c.button() > 2) {
            throw new IllegalArgumentException("button " + c.button() + " is not 1, 2 or 0 (either)");
        }
        ZoneId zone;
        try {
            zone = c.timeZone() == null || c.timeZone().isBlank() ? ZoneId.systemDefault()
                    : ZoneId.of(c.timeZone().strip());
        } catch (DateTimeException e) {
            throw new IllegalArgumentException("timeZone '" + c.timeZone() + "' is not a time zone, e.g. Europe/Berlin");
        }
        return new HelpSettings(Duration.ofMillis(c.holdMillis()), Duration.ofSeconds(c.cancelSeconds()), c.button(),
                zone);
    }

    /** @return whether presses of {@code b} count */
    boolean isHelpSwitch(int b) {
        return button == 0 || button == b;
    }
}
