package org.tinysep.launcher;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * What a launch achieved, for the banner.
 *
 * @param version    the TinySEP version
 * @param took       time from launch to the framework reaching its start level
 * @param startLevel the framework's active start level
 * @param daemon     whether it runs without the interactive shell
 * @param active     number of ACTIVE bundles per group label (e.g. {@code 1-boot → 6}), in start order
 * @param installed  number of bundles installed from {@code bundles/}
 * @param failures   the bundles that are not active, each with a one-line reason
 */
public record StartReport(String version, Duration took, int startLevel, boolean daemon,
                          Map<String, Integer> active, int installed, List<Failure> failures, List<String> warnings) {

    /** A report without warnings. */
    public StartReport(String version, Duration took, int startLevel, boolean daemon, Map<String, Integer> active,
            int installed, List<Failure> failures) {
        this(version, took, startLevel, daemon, active, installed, failures, List.of());
    }

    /** @return this report with the {@code WARNING: …} lines of the signals recorded during the start */
    public StartReport withWarnings(List<String> lines) {
        return new StartReport(version, took, startLevel, daemon, active, installed, failures, List.copyOf(lines));
    }

    /**
     * A bundle that did not resolve or start.
     *
     * @param bundle {@code symbolic-name version} or the jar file name
     * @param group  its group label
     * @param reason one line, no stack trace
     */
    public record Failure(String bundle, String group, String reason) {
    }

    /** @return total active bundles from {@code bundles/} */
    public int activeCount() {
        return active.values().stream().mapToInt(Integer::intValue).sum();
    }

    /**
     * @return the one-line banner, one line per failed bundle, then one {@code WARNING: …} line per "monitoring
     *         reduced" signal recorded during the start
     */
    public List<String> lines() {
        List<String> groups = new ArrayList<>();
        active.forEach((group, n) -> groups.add(group + " " + n));
        String mode = daemon ? "daemon" : "interactive";
        String banner = String.format(Locale.ROOT,
                "TinySEP %s up in %.1f s (%s, start level %d): %d/%d bundles active [%s]%s",
                version, took.toMillis() / 1000.0, mode, startLevel, activeCount(), installed,
                String.join(", ", groups),
                failures.isEmpty() ? "" : " — " + failures.size() + " FAILED, see below");
        List<String> lines = new ArrayList<>();
        lines.add(banner);
        failures.forEach(f -> lines.add("  FAILED " + f.bundle() + " (" + f.group() + "): " + f.reason()));
        lines.addAll(warnings == null ? List.of() : warnings);
        return lines;
    }
}
