package org.tinysep.amica.protocol;

/**
 * Light Control payload {@code 5 2 0 A}: A = light brightness in percent, 0..100. Sent by dimmable and simple
 * light nodes to report the current value, and sent by the platform to set it.
 *
 * @param percent the light brightness, 0..100
 */
public record LightControl(int percent) implements AmicaPayload {

    /** @throws IllegalArgumentException if percent is outside 0..100 */
    public LightControl {
        Percent.check(percent);
    }
}
