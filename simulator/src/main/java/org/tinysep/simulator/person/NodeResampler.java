package org.tinysep.simulator.person;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.sensor.person.Acceleration;

/**
 * What the person node's accelerometer would have measured: each of SisFall's 200 Hz samples clipped per axis to
 * the node's ±6 g (where its sensor saturates), then averaged in fours to the node's 50 Hz (a low-pass like the
 * sensor's own at that rate) (the Sun SPOT's LIS3L02AQ has the ranges ±2 g and ±6 g; the
 * node uses ±6 g so impacts, 2–6 g at the waist, are not cut at 2 g).
 */
public final class NodeResampler {

    /** The node's sample rate. */
    public static final int NODE_RATE_HZ = 50;
    /** The node's range per axis, milli-g. */
    public static final int RANGE_MG = 6000;

    private NodeResampler() {
    }

    /** @return the recording at {@value #NODE_RATE_HZ} Hz, clipped to ±{@value #RANGE_MG} mg */
    public static List<Acceleration> toNode(SisfallRecording r) {
        int factor = SisfallRecording.RATE_HZ / NODE_RATE_HZ;
        List<Acceleration> out = new ArrayList<>(r.size() / factor);
        for (int i = 0; i + factor <= r.size(); i += factor) {
            out.add(new Acceleration(mean(r.x(), i, factor), mean(r.y(), i, factor), mean(r.z(), i, factor)));
        }
        return out;
    }

    private static int mean(int[] v, int from, int n) {
        long sum = 0;
        for (int i = from; i < from + n; i++) {
            sum += clip(v[i]);
        }
        return (int) Math.round(sum / (double) n);
    }

    static int clip(int mg) {
        return Math.max(-RANGE_MG, Math.min(RANGE_MG, mg));
    }
}
