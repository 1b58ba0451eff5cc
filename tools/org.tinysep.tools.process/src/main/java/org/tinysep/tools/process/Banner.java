package org.tinysep.tools.process;

import java.time.Duration;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The launcher's start banner, e.g. {@code TinySEP 0.1.0-SNAPSHOT up in 1.2 s (interactive, start level 6): 41/41
 * bundles active [1-core 12, …]} (the launcher's {@code StartReport}), with when it came. A prompt printed on the
 * same line before it (a shell that started first) is not part of it.
 *
 * @param line        the line as printed
 * @param version     the distribution's version
 * @param upSeconds   the start time the launcher measured itself
 * @param mode        {@code interactive} or {@code daemon}
 * @param active      bundles active
 * @param installed   bundles installed
 * @param failed      bundles that failed to start ({@code — n FAILED} at the end of the line)
 * @param msFromStart wall time from starting the process to reading the line, in ms
 * @param cpu         the child's CPU time (user + system) when the line was read; null when the system does not say
 */
public record Banner(String line, String version, double upSeconds, String mode, int active, int installed,
        int failed, double msFromStart, Duration cpu) {

    private static final Pattern FORMAT = Pattern.compile("TinySEP (\\S+) up in ([0-9.]+) s \\((\\w+), start level"
            + " \\d+\\): (\\d+)/(\\d+) bundles active \\[[^\\]]*\\](?: — (\\d+) FAILED.*)?$");

    /** @return true if {@code line} is a start banner */
    public static boolean is(String line) {
        return FORMAT.matcher(line.strip()).find();
    }

    /**
     * @param line        a line of the child's standard output
     * @param msFromStart wall time since the process was started, in ms
     * @param cpu         the child's CPU time at this moment, or null
     * @return the banner's figures, or empty if {@code line} is not the banner
     */
    public static Optional<Banner> parse(String line, double msFromStart, Duration cpu) {
        Matcher m = FORMAT.matcher(line.strip());
        if (!m.find()) {
            return Optional.empty();
        }
        return Optional.of(new Banner(m.group(), m.group(1), Double.parseDouble(m.group(2)), m.group(3),
                Integer.parseInt(m.group(4)), Integer.parseInt(m.group(5)),
                m.group(6) == null ? 0 : Integer.parseInt(m.group(6)), msFromStart, cpu));
    }

    /** @return the child's CPU time to the banner in ms; NaN when unknown */
    public double cpuMs() {
        return cpu == null ? Double.NaN : cpu.toNanos() / 1e6;
    }

    /** @return true when every installed bundle is active and none failed */
    public boolean allActive() {
        return failed == 0 && active == installed;
    }
}
