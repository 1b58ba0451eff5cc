package org.tinysep.amica.protocol;

/**
 * Speaker Control payload {@code 5 4 0 A}: A = volume in percent, 0..100. Sent by speaker nodes to report the
 * current value, and sent by the platform to set it.
 *
 * @param percent the volume, 0..100
 */
public record SpeakerControl(int percent) implements AmicaPayload {

    /** @throws IllegalArgumentException if percent is outside 0..100 */
    public SpeakerControl {
        Percent.check(percent);
    }
}
