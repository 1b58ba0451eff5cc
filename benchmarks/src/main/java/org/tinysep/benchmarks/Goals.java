package org.tinysep.benchmarks;

import java.util.ArrayList;
import java.util.List;

/**
 * The performance goals (benchmarks/README.md), each MET or MISSED, from the headline figures the steps recorded
 * in the {@link Report} ({@link Report#figure}), with the ratio to the floor measured in the same run. A goal whose
 * figure no step produced says "not measured". Figure keys (one value per run of the step; a step repeated n times
 * gives n):
 * <ul>
 * <li>{@code throughput.platform}, {@code throughput.bare}: highest loss-free frames/s, TinySEP and bare receiver</li>
 * <li>{@code latency.p50}, {@code latency.p99}, {@code latency.pacedP50}, {@code latency.pacedP99}: µs at 1,000
 * background frames/s, TinySEP and the bare UDP echo paced like TinySEP's samples (the floor); {@code
 * latency.echoP50}, {@code latency.echoP99}: the echo back to back (the machine's best case, reported beside)</li>
 * <li>{@code thesis.s5cpu}, {@code thesis.idleCpu}, {@code thesis.felixIdleCpu} (a bare Felix framework over the same
 * window, the idle goal's floor): % of one core</li>
 * <li>{@code start.bannerMs}, {@code start.felixMs}: start to the banner, TinySEP and bare Felix</li>
 * <li>{@code rss.defaultKb}, {@code rss.headlessKb}, {@code rss.felixKb}: idle RSS, default and headless
 * distribution and bare Felix</li>
 * <li>{@code scale.create.20000.ms}, {@code scale.stop.20000.ms}, {@code scale.restored.20000.ms}: 20,000 devices</li>
 * </ul>
 */
final class Goals {

    /**
     * @param key     the figure's key
     * @param floor   the floor's key (null: none)
     * @param limit   the goal, in the figure's unit (for {@code onRatio}: the least ratio to the floor)
     * @param atMost  lower is better
     * @param onRatio the goal is on the ratio to the floor, not on the figure
     * @param divisor shown value = figure / divisor, in {@code unit}
     */
    record Goal(String text, String key, String floor, double limit, boolean atMost, boolean onRatio,
            double divisor, String unit) {
    }

    static final List<Goal> ISSUE_29 = List.of(
            new Goal("loss-free throughput ≥ 100,000 frames/s", "throughput.platform", "throughput.bare", 100_000,
                    false, false, 1, "frames/s"),
            new Goal("loss-free throughput ≥ 40 % of the bare receiver", "throughput.platform", "throughput.bare",
                    0.40, false, true, 1, "frames/s"),
            new Goal("packet → light p50 ≤ 150 µs at 1,000 frames/s", "latency.p50", "latency.pacedP50", 150, true,
                    false, 1, "µs"),
            new Goal("packet → light p99 ≤ 1 ms at 1,000 frames/s", "latency.p99", "latency.pacedP99", 1_000, true,
                    false, 1, "µs"),
            new Goal("thesis scenario 5 ≤ 0.5 % of one core", "thesis.s5cpu", "thesis.idleCpu", 0.5, true, false, 1,
                    "%"),
            new Goal("idle ≤ 0.1 % of one core", "thesis.idleCpu", "thesis.felixIdleCpu", 0.1, true, false, 1, "%"),
            new Goal("start to the banner ≤ 1 s", "start.bannerMs", "start.felixMs", 1_000, true, false, 1_000, "s"),
            new Goal("idle RSS, default distribution ≤ 80 MB", "rss.defaultKb", "rss.felixKb", 80 * 1024, true,
                    false, 1024, "MB"),
            new Goal("idle RSS, headless gateway ≤ 64 MB", "rss.headlessKb", "rss.felixKb", 64 * 1024, true, false,
                    1024, "MB"),
            new Goal("20,000 devices created ≤ 10 s", "scale.create.20000.ms", null, 10_000, true, false, 1_000, "s"),
            new Goal("orderly stop of 20,000 devices ≤ 5 s", "scale.stop.20000.ms", null, 5_000, true, false, 1_000,
                    "s"),
            new Goal("restart to 20,000 devices restored ≤ 5 s", "scale.restored.20000.ms", null, 5_000, true, false,
                    1_000, "s"));

    private Goals() {
    }

    /** @return the goals table (Markdown) */
    static String markdown(Report r) {
        return markdown(r, null);
    }

    /**
     * @param before the previous run's figures ({@link Before}), or null for no "before" column
     * @return the goals table (Markdown)
     */
    static String markdown(Report r, Report before) {
        StringBuilder md = new StringBuilder("\n## Issue 29 goals: met or missed (ratio to the floor of the same run)"
                + "\n\n")
                .append("Each figure is the median over the runs of its step (min–max beside it: the spread); the "
                        + "ratio is TinySEP ÷ the floor measured in the same run (median of the per-run ratios); "
                        + "the verdict is on the median.")
                .append(before == null ? "" : " *Before*: the previous run's median and its ratio to its own floor "
                        + "(RESULTS-before.md; \"–\": that run did not measure it).")
                .append("\n\n| goal | TinySEP: median (min–max, runs) | floor, same run | ratio to floor | verdict |")
                .append(before == null ? "\n|---|---|---|---|---|\n" : " before: median (ratio) |\n|---|---|---|---|---|---|\n");
        for (Goal g : ISSUE_29) {
            List<String> row = row(r, g);
            md.append("| ").append(String.join(" | ", row));
            if (before != null) {
                List<String> was = row(before, g);
                md.append(" | ").append(was.get(1).equals("not measured") ? "–"
                        : was.get(1).replaceFirst(" \\(.*", "") + (was.get(3).equals("–") ? ""
                                : " (" + was.get(3).replaceFirst(" \\(.*", "") + ")"));
            }
            md.append(" |\n");
        }
        return md.append('\n').toString();
    }

    /** @return one line per goal, for the console: "MET    idle ≤ 0.1 % …: 0.08 % (ratio …)" */
    static List<String> lines(Report r) {
        List<String> out = new ArrayList<>();
        for (Goal g : ISSUE_29) {
            List<String> row = row(r, g);
            out.add(row.get(4).replace("**", "") + " — " + g.text() + ": " + row.get(1) + "; floor " + row.get(2)
                    + "; ratio " + row.get(3));
        }
        return out;
    }

    private static List<String> row(Report r, Goal g) {
        List<Double> v = r.figures(g.key());
        List<Double> f = g.floor() == null ? List.of() : r.figures(g.floor());
        List<Double> ratios = new ArrayList<>();
        if (v.size() == f.size()) {
            for (int i = 0; i < v.size(); i++) {
                ratios.add(f.get(i) > 0 ? v.get(i) / f.get(i) : Double.NaN);
            }
        }
        double value = Report.median(v);
        double ratio = Report.median(ratios);
        String shown = Double.isNaN(value) ? "not measured" : Report.f("%s %s (%s–%s, %d run%s)", num(value / g.divisor()),
                g.unit(), num(Report.min(v) / g.divisor()), num(Report.max(v) / g.divisor()), v.size(),
                v.size() == 1 ? "" : "s");
        String floor = g.floor() == null ? "–" : f.isEmpty() ? "not measured"
                : num(Report.median(f) / g.divisor()) + " " + g.unit();
        String ratioText = Double.isNaN(ratio) ? "–" : ratios.size() == 1 ? Report.f("%.2f×", ratio)
                : Report.f("%.2f× (%.2f–%.2f)", ratio, Report.min(ratios), Report.max(ratios));
        double judged = g.onRatio() ? ratio : value;
        String verdict;
        if (Double.isNaN(judged)) {
            verdict = "not measured";
        } else {
            boolean met = g.atMost() ? judged <= g.limit() : judged >= g.limit();
            List<Double> each = g.onRatio() ? ratios : v;
            long metRuns = each.stream().filter(x -> !Double.isNaN(x))
                    .filter(x -> g.atMost() ? x <= g.limit() : x >= g.limit()).count();
            verdict = (met ? "MET" : "**MISSED**") + Report.f(" (%s; met in %d of %d runs)",
                    g.onRatio() ? Report.f("%.0f %% of the floor, goal %.0f %%", 100 * judged, 100 * g.limit())
                            : Report.f("%.2f× the goal", judged / g.limit()), metRuns, each.size());
        }
        return List.of(g.text(), shown, floor, ratioText, verdict);
    }

    private static String num(double d) {
        return Math.abs(d) >= 100 ? Report.f("%,.0f", d) : Math.abs(d) >= 10 ? Report.f("%.1f", d)
                : Report.f("%.2f", d);
    }
}
