package org.tinysep.sunspot.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * One chunk of a person node's acceleration burst {@code 6 0x31 ...} (TinySEP, protocol 2.2.0): the raw samples
 * around an acceleration peak, cut into chunks of at most {@value #MAX_SAMPLES} samples so that a frame stays within
 * 200 payload bytes. Chunk i holds samples {@code 32·i ..}; every chunk but the last holds exactly 32. All chunks of
 * a burst repeat its id, chunk count, sample rate and samples before the trigger, so each chunk can be checked alone.
 * <p>
 * Limits (the decoder refuses a chunk beyond them as {@link RejectReason#BAD_VALUE}): burst id 0..255; chunk count
 * 1..{@value #MAX_CHUNKS}; index below the count; sample rate 1..255 Hz; 1..32 samples, exactly 32 unless last;
 * each axis within ±{@value AccelerationSample#LIMIT_MG} mg; the trigger sample inside the burst
 * (samples before the trigger below 32 · count, and below the burst's length in the last chunk).
 *
 * @param burstId              the node's number for this burst, 0..255 (wraps)
 * @param chunkIndex           0..chunkCount-1
 * @param chunkCount           how many chunks the burst has, 1..{@value #MAX_CHUNKS}
 * @param sampleRateHz         samples per second, 1..255
 * @param samplesBeforeTrigger how many samples of the whole burst precede the trigger sample
 * @param samples              this chunk's samples, oldest first
 */
public record BurstChunk(int burstId, int chunkIndex, int chunkCount, int sampleRateHz, int samplesBeforeTrigger,
        List<AccelerationSample> samples) implements SunSpotPayload {

    /** Most samples in one chunk. */
    public static final int MAX_SAMPLES = 32;
    /** Most chunks in one burst (512 samples, about 10 s at 50 Hz). */
    public static final int MAX_CHUNKS = 16;

    /** @throws IllegalArgumentException if a value breaks a limit above */
    public BurstChunk {
        samples = List.copyOf(samples);
        String fault = fault(burstId, chunkIndex, chunkCount, sampleRateHz, samplesBeforeTrigger, samples.size());
        if (fault != null) {
            throw new IllegalArgumentException(fault);
        }
    }

    /** @return true if this is the burst's last chunk */
    public boolean last() {
        return chunkIndex == chunkCount - 1;
    }

    /**
     * Cuts a burst into its chunks, as a node sends them.
     *
     * @param burstId              0..255
     * @param sampleRateHz         1..255
     * @param samplesBeforeTrigger how many samples precede the trigger sample
     * @param samples              the whole burst, 1..{@value #MAX_CHUNKS}·{@value #MAX_SAMPLES} samples
     * @return the chunks in order
     * @throws IllegalArgumentException if the burst breaks a limit
     */
    public static List<BurstChunk> split(int burstId, int sampleRateHz, int samplesBeforeTrigger,
            List<AccelerationSample> samples) {
        Objects.requireNonNull(samples, "samples");
        int count = (samples.size() + MAX_SAMPLES - 1) / MAX_SAMPLES;
        if (count < 1 || count > MAX_CHUNKS) {
            throw new IllegalArgumentException("a burst has 1.." + MAX_CHUNKS * MAX_SAMPLES + " samples, not "
                    + samples.size());
        }
        List<BurstChunk> chunks = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            chunks.add(new BurstChunk(burstId, i, count, sampleRateHz, samplesBeforeTrigger,
                    samples.subList(i * MAX_SAMPLES, Math.min(samples.size(), (i + 1) * MAX_SAMPLES))));
        }
        return chunks;
    }

    /** @return why a chunk with these values cannot come from a node, in words, or null if it can */
    static String fault(int burstId, int chunkIndex, int chunkCount, int sampleRateHz, int samplesBeforeTrigger,
            int size) {
        if (burstId < 0 || burstId > 255) {
            return "burst id " + burstId + ", expected 0..255";
        }
        if (chunkCount < 1 || chunkCount > MAX_CHUNKS) {
            return "chunk count " + chunkCount + ", expected 1.." + MAX_CHUNKS;
        }
        if (chunkIndex < 0 || chunkIndex >= chunkCount) {
            return "chunk index " + chunkIndex + " of " + chunkCount + " chunks";
        }
        if (sampleRateHz < 1 || sampleRateHz > 255) {
            return "sample rate " + sampleRateHz + " Hz, expected 1..255";
        }
        boolean last = chunkIndex == chunkCount - 1;
        if (size < 1 || size > MAX_SAMPLES || !last && size != MAX_SAMPLES) {
            return "chunk " + chunkIndex + " of " + chunkCount + " holds " + size + " samples, expected "
                    + (last ? "1.." + MAX_SAMPLES : "exactly " + MAX_SAMPLES + " (not the last chunk)");
        }
        int known = last ? (chunkCount - 1) * MAX_SAMPLES + size : chunkCount * MAX_SAMPLES;
        if (samplesBeforeTrigger < 0 || samplesBeforeTrigger >= known) {
            return samplesBeforeTrigger + " samples before the trigger, but the burst has "
                    + (last ? "" : "at most ") + known + " samples: the trigger sample would lie outside it";
        }
        return null;
    }

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.PERSON;
    }
}
