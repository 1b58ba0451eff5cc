package org.tinysep.simulator.person;

import java.io.IOException;
import java.io.OutputStream;
import java.io.Writer;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.zip.GZIPOutputStream;

/**
 * Writes recordings in SisFall's format (200 Hz, nine columns, ADXL345 counts first) of a made-up wearer, for tests
 * and the smoke run: SisFall itself states no licence that allows copying it into this repository
 * (docs/fall-detection.md). Not data from a person: a walk, a fall and the everyday movements that look like one,
 * drawn from simple shapes with seeded noise.
 */
public final class SyntheticRecordings {

    /** The codes written per subject: two falls, three daily activities (walk, sit down, jump). */
    public static final List<String> CODES = List.of("F01", "F13", "D01", "D07", "D19");
    private static final int RATE = SisfallRecording.RATE_HZ;
    private static final double COUNTS_PER_G = 1000 / SisfallRecording.MG_PER_COUNT;

    private SyntheticRecordings() {
    }

    /** Writes {@code <folder>/<subject>/<code>_<subject>_R01.txt.gz} for every code of {@link #CODES}. */
    public static void write(Path folder, String subject, long seed) throws IOException {
        Path dir = Files.createDirectories(folder.resolve(subject));
        for (String code : CODES) {
            write(dir.resolve(code + "_" + subject + "_R01.txt.gz"), samples(code, new Random(seed ^ code.hashCode())));
        }
    }

    /** @return per sample x, y, z in g: the node's y axis points down when upright (SisFall's waist device) */
    static double[][] samples(String code, Random rnd) {
        int n = (code.startsWith("F") ? 15 : 12) * RATE;
        double[][] g = new double[n][];
        int event = 4 * RATE;
        for (int i = 0; i < n; i++) {
            double t = i / (double) RATE;
            double noise = rnd.nextGaussian() * 0.02;
            boolean walking = !code.equals("F13") && !code.equals("D07");
            double step = walking ? 0.35 * Math.sin(2 * Math.PI * 1.8 * t) : 0;
            double[] upright = {noise, -1 - step + noise, 0.05 * step + noise};
            if (code.equals("D01") || i < event) {
                g[i] = upright;
            } else if (code.startsWith("F")) {
                int k = i - event; // 0.4 s falling, an impact of 3.5 g, lying on the back
                if (k < 0.4 * RATE) {
                    g[i] = new double[] {0.1 + noise, -0.3 + noise, 0.1 + noise};
                } else if (k < 0.4 * RATE + 6) {
                    g[i] = new double[] {0.8, -1.5, 3.0};
                } else {
                    double settle = Math.exp(-(k - 0.4 * RATE) / (0.3 * RATE));
                    g[i] = new double[] {0.05 + noise + 0.3 * settle, -0.1 + noise, 0.99 + noise};
                }
            } else if (code.equals("D07")) {
                double tilt = Math.toRadians(25) * Math.min(1, (i - event) / (1.5 * RATE)); // sits down slowly
                g[i] = new double[] {noise, -Math.cos(tilt) + noise, Math.sin(tilt) + noise};
            } else { // D19: a jump every 3 s, landing at 2.6 g, standing still between
                int k = (i - event) % (3 * RATE);
                double y = k < 0.3 * RATE ? -0.2 : k < 0.3 * RATE + 5 ? -2.6 : -1;
                g[i] = new double[] {noise, y + noise, noise};
            }
        }
        return g;
    }

    private static void write(Path file, double[][] g) throws IOException {
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(file));
                Writer w = new OutputStreamWriter(out, StandardCharsets.US_ASCII)) {
            for (double[] s : g) {
                w.write(String.format(java.util.Locale.ROOT, "%d,%d,%d,0,0,0,0,0,0;%n", count(s[0]), count(s[1]),
                        count(s[2])));
            }
        }
    }

    private static long count(double gValue) {
        return Math.round(gValue * COUNTS_PER_G);
    }
}
