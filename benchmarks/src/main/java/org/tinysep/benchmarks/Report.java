package org.tinysep.benchmarks;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The Markdown of RESULTS.md, built section by section. */
final class Report {

    private final StringBuilder md = new StringBuilder();
    final List<String> problems = new ArrayList<>();

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
