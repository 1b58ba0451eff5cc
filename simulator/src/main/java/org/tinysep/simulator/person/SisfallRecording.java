package org.tinysep.simulator.person;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.GZIPInputStream;

/**
 * One SisFall recording (Sucerquia et al. 2017): the ADXL345's acceleration at 200 Hz, in milli-g. The file is
 * {@code <code>_<subject>_<trial>.txt} (or {@code .txt.gz}), one sample a line, nine comma-separated integers ending
 * in {@code ;}; the first three are the ADXL345's x, y, z counts (13 bit, ±16 g: 1 count = 32 g / 8192 = 3.90625 mg).
 *
 * @param code    activity code, {@code F01}..{@code F15} (falls) or {@code D01}..{@code D19} (daily activities)
 * @param subject subject id, e.g. {@code SA01}
 * @param trial   trial, e.g. {@code R01}
 * @param x       x axis per sample, milli-g
 * @param y       y axis per sample, milli-g
 * @param z       z axis per sample, milli-g
 */
public record SisfallRecording(String code, String subject, String trial, int[] x, int[] y, int[] z) {

    /** SisFall's sample rate. */
    public static final int RATE_HZ = 200;
    /** Milli-g per ADXL345 count at ±16 g, 13 bit. */
    public static final double MG_PER_COUNT = 32_000.0 / 8192;

    private static final Pattern NAME = Pattern.compile("([DF]\\d\\d)_([A-Z]{2}\\d\\d)_(R\\d\\d)\\.txt(\\.gz)?");

    public SisfallRecording {
        if (x.length != y.length || y.length != z.length) {
            throw new IllegalArgumentException("axes of different lengths");
        }
    }

    /** @return whether the file name looks like a SisFall recording */
    public static boolean isRecording(Path file) {
        return NAME.matcher(file.getFileName().toString()).matches();
    }

    /**
     * Reads a recording.
     *
     * @throws IllegalArgumentException for a name or a line that is not SisFall's, saying which file and line
     */
    public static SisfallRecording read(Path file) throws IOException {
        Matcher m = NAME.matcher(file.getFileName().toString());
        if (!m.matches()) {
            throw new IllegalArgumentException(file + ": not a SisFall recording's name (<code>_<subject>_<trial>.txt"
                    + " or .txt.gz, e.g. F01_SA01_R01.txt.gz)");
        }
        try (InputStream raw = Files.newInputStream(file);
                InputStream in = m.group(4) != null ? new GZIPInputStream(raw) : raw;
                BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.US_ASCII))) {
            return parse(m.group(1), m.group(2), m.group(3), r, file.toString());
        }
    }

    /**
     * Reads a recording from a stream, e.g. one shipped inside the simulator's jar.
     *
     * @param name the recording's file name (SisFall's: {@code F01_SX01_R01.txt.gz}; {@code .gz}: compressed)
     */
    public static SisfallRecording read(String name, InputStream stream) throws IOException {
        Matcher m = NAME.matcher(name);
        if (!m.matches()) {
            throw new IllegalArgumentException(name + ": not a SisFall recording's name");
        }
        try (InputStream in = m.group(4) != null ? new GZIPInputStream(stream) : stream;
                BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.US_ASCII))) {
            return parse(m.group(1), m.group(2), m.group(3), r, name);
        }
    }

    private static SisfallRecording parse(String code, String subject, String trial, BufferedReader r, String where)
            throws IOException {
        int[][] axes = new int[3][4096];
        int n = 0;
        int lineNo = 0;
        for (String line; (line = r.readLine()) != null;) {
            lineNo++;
            String s = line.strip();
            if (s.isEmpty()) {
                continue;
            }
            if (s.endsWith(";")) {
                s = s.substring(0, s.length() - 1);
            }
            String[] f = s.split(",");
            if (f.length != 9) {
                throw new IllegalArgumentException(where + " line " + lineNo + ": " + f.length
                        + " columns, a SisFall line has 9 (ADXL345 x y z, ITG3200 x y z, MMA8451Q x y z)");
            }
            if (n == axes[0].length) {
                for (int a = 0; a < 3; a++) {
                    axes[a] = Arrays.copyOf(axes[a], n * 2);
                }
            }
            for (int a = 0; a < 3; a++) {
                try {
                    axes[a][n] = (int) Math.round(Integer.parseInt(f[a].strip()) * MG_PER_COUNT);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException(where + " line " + lineNo + ": '" + f[a].strip()
                            + "' is not a whole number of counts");
                }
            }
            n++;
        }
        if (n == 0) {
            throw new IllegalArgumentException(where + ": no samples");
        }
        return new SisfallRecording(code, subject, trial, Arrays.copyOf(axes[0], n), Arrays.copyOf(axes[1], n),
                Arrays.copyOf(axes[2], n));
    }

    /** @return whether this is a fall (codes F..) rather than a daily activity (D..) */
    public boolean isFall() {
        return code.startsWith("F");
    }

    /** @return samples */
    public int size() {
        return x.length;
    }

    /** @return {@code code_subject_trial} */
    public String name() {
        return code + "_" + subject + "_" + trial;
    }

    /** @return the index of the sample with the largest magnitude (the impact of a fall) */
    public int peakIndex() {
        int best = 0;
        double max = -1;
        for (int i = 0; i < x.length; i++) {
            double m = (double) x[i] * x[i] + (double) y[i] * y[i] + (double) z[i] * z[i];
            if (m > max) {
                max = m;
                best = i;
            }
        }
        return best;
    }
}
