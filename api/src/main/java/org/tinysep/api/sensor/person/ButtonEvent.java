package org.tinysep.api.sensor.person;

import java.time.Instant;
import java.util.Objects;

/**
 * A switch on the person node was pressed or released.
 *
 * @param button which switch: 1 or 2 (the Sun SPOT's SW1, SW2)
 * @param action pressed or released
 * @param at     when the report was received
 */
public record ButtonEvent(int button, ButtonAction action, Instant at) {

    public ButtonEvent {
        Objects.requireNonNull(action, "action");
        Objects.requireNonNull(at, "at");
        if (button < 1 || button > 2) {
            throw new IllegalArgumentException("a Sun SPOT has switches 1 and 2, not " + button);
        }
    }
}
