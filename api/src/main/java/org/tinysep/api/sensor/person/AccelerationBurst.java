package org.tinysep.api.sensor.person;

import java.time.Instant;
import java.util.List;
import java.util.Objects;

/**
 * The raw samples a person node sends around an acceleration peak: from a little before the first sample above its
 * trigger level to a few seconds after it, at the node's sample rate.
 *
 * @param trigger              when the first sample above the trigger level was taken (platform time)
 * @param sampleRateHz         samples per second
 * @param samplesBeforeTrigger how many of {@code samples} precede the trigger sample
 * @param samples              the samples, oldest first
 */
public record AccelerationBurst(Instant trigger, int sampleRateHz, int samplesBeforeTrigger,
        List<Acceleration> samples) {

    public AccelerationBurst {
        Objects.requireNonNull(trigger, "trigger");
        samples = List.copyOf(samples);
        if (sampleRateHz <= 0 || samplesBeforeTrigger < 0 || samplesBeforeTrigger > samples.size()) {
            throw new IllegalArgumentException("inconsistent burst: rate " + sampleRateHz + " Hz, "
                    + samplesBeforeTrigger + " samples before the trigger of " + samples.size());
        }
    }
}
