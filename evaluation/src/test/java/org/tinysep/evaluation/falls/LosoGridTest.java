package org.tinysep.evaluation.falls;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.falldetection.internal.FallSettings;
import org.tinysep.simulator.person.SisfallRecording;

/**
 * Session 31: a deliberate lie-down (SisFall D13: sitting, lying down quickly onto the back with a bump of 2.5 g,
 * still for a moment of 4.5 s, sitting up again) is no fall for any setting leave-one-subject-out may choose, while
 * the same landing followed by 10 s of stillness is one for the defaults. A made-up recording in SisFall's format
 * (200 Hz, mg), not a person's.
 */
class LosoGridTest {

    private static final int RATE = SisfallRecording.RATE_HZ;
    private static final double[] SITTING = {0, -950, -300};
    private static final double[] LYING = {-950, -100, 300};

    @Test
    void aDeliberateLieDownIsNoFallForAnySettingOfTheGrid() {
        NodeStream lieDown = NodeStream.of(lieDown("D13", 4.5));
        List<String> alerting = new ArrayList<>();
        for (FallSettings s : Loso.grid()) {
            if (!Scored.run(lieDown, s, null).alerts().isEmpty()) {
                alerting.add(FallsReport.settings(s));
            }
        }
        assertEquals(List.of(), alerting, "lying still for a moment after lying down quickly alerts with");
    }

    @Test
    void theSameLandingFollowedByStillnessIsAFallWithTheDefaults() {
        assertEquals(FallSettings.DEFAULT, Loso.grid().get(0), "the grid begins with the defaults");
        Scored fall = Scored.run(NodeStream.of(lieDown("F14", 10)), FallSettings.DEFAULT, null);
        assertTrue(fall.delay().isPresent(), "lying still for 10 s after the landing: " + fall.alerts());
    }

    /** Sitting 3 s, lying down in 0.5 s with a bump at its end, still for {@code stillS}, sitting up in 1 s, sitting 3 s. */
    private static SisfallRecording lieDown(String code, double stillS) {
        Random noise = new Random(7);
        List<double[]> g = new ArrayList<>();
        hold(g, SITTING, 3, noise);
        for (int i = 0; i < RATE / 2; i++) {
            g.add(between(SITTING, LYING, i / (RATE / 2.0), noise));
        }
        for (int i = 0; i < 8; i++) { // the back meets the bed: 40 ms at 2.5 g along the lying gravity
            g.add(scaled(LYING, 2500 / norm(LYING)));
        }
        hold(g, LYING, stillS, noise);
        for (int i = 0; i < RATE; i++) { // sitting up: a moving trunk
            double[] a = between(LYING, SITTING, i / (double) RATE, noise);
            g.add(scaled(a, 1 + 0.5 * Math.sin(2 * Math.PI * 3 * i / RATE)));
        }
        hold(g, SITTING, 3, noise);
        int n = g.size();
        int[] x = new int[n];
        int[] y = new int[n];
        int[] z = new int[n];
        for (int i = 0; i < n; i++) {
            x[i] = (int) Math.round(g.get(i)[0]);
            y[i] = (int) Math.round(g.get(i)[1]);
            z[i] = (int) Math.round(g.get(i)[2]);
        }
        return new SisfallRecording(code, "SX09", "R01", x, y, z);
    }

    private static void hold(List<double[]> g, double[] v, double seconds, Random noise) {
        for (int i = 0; i < seconds * RATE; i++) {
            g.add(new double[] {v[0] + noise.nextGaussian() * 8, v[1] + noise.nextGaussian() * 8,
                    v[2] + noise.nextGaussian() * 8});
        }
    }

    private static double[] between(double[] a, double[] b, double f, Random noise) {
        double[] v = new double[3];
        for (int k = 0; k < 3; k++) {
            v[k] = a[k] + (b[k] - a[k]) * f;
        }
        double[] u = scaled(v, 1000 / norm(v));
        return new double[] {u[0] + noise.nextGaussian() * 8, u[1] + noise.nextGaussian() * 8,
                u[2] + noise.nextGaussian() * 8};
    }

    private static double[] scaled(double[] v, double f) {
        return new double[] {v[0] * f, v[1] * f, v[2] * f};
    }

    private static double norm(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
}
