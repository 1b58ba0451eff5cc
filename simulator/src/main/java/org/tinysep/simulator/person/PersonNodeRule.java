package org.tinysep.simulator.person;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;

/**
 * What the worn person node computes from its 50 Hz samples (docs/protocols/sunspot.md, "Person node"): a movement
 * summary every 2 s (mean x, y, z; standard deviation and peak of the magnitude) and, when the magnitude reaches
 * the trigger level ({@value #TRIGGER_MG} mg), a burst of the raw samples from 1 s before the trigger sample to 2 s
 * after it (150 samples), sent when complete. A trigger during a burst belongs to it; the next burst can start with
 * the sample after it.
 */
public final class PersonNodeRule {

    /** The magnitude that starts a burst, milli-g: 2 g, Fall Detection's lowest impact level (a burst below it is of no use; at 1.8 g walking sent 47 % more bursts with the same detections, docs/fall-detection.md). */
    public static final int TRIGGER_MG = 2000;
    public static final int RATE_HZ = NodeResampler.NODE_RATE_HZ;
    public static final int SUMMARY_SAMPLES = 2 * RATE_HZ;
    public static final int BEFORE_SAMPLES = RATE_HZ;
    public static final int BURST_SAMPLES = 3 * RATE_HZ;

    /** Receives what the node sends, at the instant it is complete. */
    public interface Output {
        void summary(Instant at, MovementSummary summary);

        void burst(Instant at, AccelerationBurst burst);
    }

    private final Output out;
    private final ArrayDeque<Acceleration> recent = new ArrayDeque<>();
    private final List<Acceleration> period = new ArrayList<>(SUMMARY_SAMPLES);
    private List<Acceleration> burst;
    private int burstBefore;
    private Instant trigger;

    public PersonNodeRule(Output out) {
        this.out = out;
    }

    /** One sample, taken at {@code at} (samples come every 20 ms). */
    public void sample(Instant at, Acceleration a) {
        double magnitude = a.magnitudeMg();
        if (burst != null) {
            burst.add(a);
        } else if (magnitude >= TRIGGER_MG) {
            burst = new ArrayList<>(recent);
            burstBefore = burst.size();
            burst.add(a);
            trigger = at;
        }
        if (burst != null && burst.size() == burstBefore + BURST_SAMPLES - BEFORE_SAMPLES) {
            out.burst(at, new AccelerationBurst(trigger, RATE_HZ, burstBefore, burst));
            burst = null;
        }
        recent.addLast(a);
        if (recent.size() > BEFORE_SAMPLES) {
            recent.removeFirst();
        }
        period.add(a);
        if (period.size() == SUMMARY_SAMPLES) {
            out.summary(at, summarise(at, period));
            period.clear();
        }
    }

    static MovementSummary summarise(Instant end, List<Acceleration> samples) {
        double sm = 0;
        double sm2 = 0;
        double peak = 0;
        for (Acceleration a : samples) {
            double m = a.magnitudeMg();
            sm += m;
            sm2 += m * m;
            peak = Math.max(peak, m);
        }
        int n = samples.size();
        double mean = sm / n;
        double sd = Math.sqrt(Math.max(0, sm2 / n - mean * mean));
        return new MovementSummary(end, Duration.ofMillis(1000L * n / RATE_HZ),
                Acceleration.mean(samples),
                (int) Math.round(sd), (int) Math.round(peak));
    }
}
