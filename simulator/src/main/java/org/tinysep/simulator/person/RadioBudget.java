package org.tinysep.simulator.person;

import java.time.Duration;
import java.util.Locale;

/**
 * What the person node's rule costs on the radio: frames and bytes, counted from the rule's output as
 * docs/protocols/sunspot.md ("Radio budget") counts them: every frame is {@value #FRAME_HEADER_BYTES} bytes of
 * header plus its payload. A summary's payload is {@value #SUMMARY_BYTES} bytes ({@code 6 0x21 span-ms(u16) meanX
 * meanY meanZ (s16) sd(u16) peak(u16)}); a burst is {@value #CHUNKS_PER_BURST} chunk frames (chunks of at most 32
 * samples) of {@code 6 0x31 id idx count rateHz before(u16)} ({@value #CHUNK_HEADER_BYTES} bytes) plus 6 bytes a
 * sample.
 */
public final class RadioBudget {

    public static final int FRAME_HEADER_BYTES = 12;
    public static final int SUMMARY_BYTES = 14;
    public static final int CHUNK_HEADER_BYTES = 8;
    public static final int CHUNKS_PER_BURST = 5;
    public static final int BYTES_PER_SAMPLE = 6;

    private long summaries;
    private long bursts;
    private long burstSamples;
    private Duration recorded = Duration.ZERO;

    /** Counts one summary frame. */
    public void summary() {
        summaries++;
    }

    /** Counts one burst of {@code samples} samples. */
    public void burst(int samples) {
        bursts++;
        burstSamples += samples;
    }

    /** Adds recorded time (the span the counted frames cover). */
    public void recorded(Duration d) {
        recorded = recorded.plus(d);
    }

    /** Adds another budget's counts and time to this one. */
    public void add(RadioBudget other) {
        summaries += other.summaries;
        bursts += other.bursts;
        burstSamples += other.burstSamples;
        recorded = recorded.plus(other.recorded);
    }

    public long frames() {
        return summaries + bursts * CHUNKS_PER_BURST;
    }

    public long bytes() {
        return summaries * (FRAME_HEADER_BYTES + SUMMARY_BYTES)
                + bursts * CHUNKS_PER_BURST * (FRAME_HEADER_BYTES + CHUNK_HEADER_BYTES)
                + burstSamples * BYTES_PER_SAMPLE;
    }

    public long bursts() {
        return bursts;
    }

    public double hours() {
        return recorded.toMillis() / 3_600_000.0;
    }

    /** @return e.g. "1 800 frames/h, 25.2 kB/h, 0.0 bursts/h" over the recorded time */
    public String perHour() {
        double h = hours();
        if (h <= 0) {
            return "no recorded time";
        }
        return String.format(Locale.ROOT, "%.0f frames/h, %.1f kB/h (%.1f bursts/h)", frames() / h,
                bytes() / h / 1000, bursts / h);
    }
}
