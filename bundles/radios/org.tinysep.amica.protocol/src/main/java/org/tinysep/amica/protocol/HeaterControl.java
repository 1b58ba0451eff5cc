package org.tinysep.amica.protocol;

/**
 * Heater Control payload {@code 5 8 0 A}: A = heater potency in percent, 0..100. Sent by heater nodes to report
 * the current value, and sent by the platform to set it.
 *
 * @param percent the heater potency, 0..100
 */
public record HeaterControl(int percent) implements AmicaPayload {

    /** @throws IllegalArgumentException if percent is outside 0..100 */
    public HeaterControl {
        Percent.check(percent);
    }
}
