package org.tinysep.benchmarks;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** The Markdown of RESULTS.md, built section by section. */
final class Report {

    private final StringBuilder md = new StringBuilder();
    final List<String> problems = new ArrayList<>();
    /** Headline figures by key, one value per run of the step (see {@link Goals} for the keys). */
    private final Map<String, List<Double>> figures = new LinkedHashMap<>();

    /** Records one run's value of a headline figure (NaN: not measured in that run). */
    void figure(String key, double value) {
        figures.computeIfAbsent(key, k -> new ArrayList<>()).add(value);
    }

    /** @return every run's value of {@code key}, in run order (empty: no step produced it) */
    List<Double> figures(String key) {
        return figures.getOrDefault(key, List.of());
    }

    /** @return the keys of every recorded figure, in the order first recorded */
    List<String> keys() {
        return List.copyOf(figures.keySet());
    }

    /** @return the median of the measured values (NaN when none) */
    static double median(List<Double> values) {
        double[] v = values.stream().mapToDouble(Double::doubleValue).filter(d -> !Double.isNaN(d)).sorted()
                .toArray();
        return v.length == 0 ? Double.NaN : v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }

    static double min(List<Double> values) {
        return values.stream().mapToDouble(Double::doubleValue).filter(d -> !Double.isNaN(d)).min().orElse(Double.NaN);
    }

    static double max(List<Double> values) {
        return values.stream().mapToDouble(Double::doubleValue).filter(d -> !Double.isNaN(d)).max().orElse(Double.NaN);
    }

    void heading(String text) {
        md.append("\n## ").append(text).append("\n\n");
    }

    void text(String text) {
        md.append(text).append("\n\n");
    }

    void table(List<String> header, List<List<String>> rows) {
        md.append("| ").append(String.join(" | ", header)).append(" |\n|");
        header.forEach(h -> md.append("---|"));
        md.append('\n');
        for (List<String> r : rows) {
            md.append("| ").append(String.join(" | ", r)).append(" |\n");
        }
        md.append('\n');
    }

    void problem(String where, Exception e) {
        String line = where + " failed: " + e;
        problems.add(line);
        text("**" + line + "**");
    }

    String markdown() {
        return md.toString();
    }

    static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }

    static String mb(long kb) {
        return kb < 0 ? "n/a" : f("%.1f MB", kb / 1024.0);
    }

    static String ratio(double value, double floor) {
        return floor <= 0 || Double.isNaN(value) || Double.isNaN(floor) ? "n/a" : f("%.2f×", value / floor);
    }

    /** "met" or "missed by …" for a goal where lower is better */
    static String goalAtMost(double value, double goal, String unit) {
        if (Double.isNaN(value)) {
            return "not measured";
        }
        return value <= goal ? "met (≤ " + f("%.2f", goal) + " " + unit + ")"
                : "**missed** by " + f("%.2f", value - goal) + " " + unit + " (" + f("%.0f", 100 * (value / goal - 1)) + " % over " + f("%.2f", goal) + ")";
    }

    /** "met" or "missed by …" for a goal where higher is better */
    static String goalAtLeast(double value, double goal, String unit) {
        if (Double.isNaN(value)) {
            return "not measured";
        }
        return value >= goal ? "met (≥ " + f("%.0f", goal) + " " + unit + ")"
                : "**missed** by " + f("%.0f", goal - value) + " " + unit + " (" + f("%.0f", 100 * (1 - value / goal)) + " % under " + f("%.0f", goal) + ")";
    }
}
