package org.tinysep.evaluation;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

/** The markdown table of one home's evaluation, detectors side by side. */
final class Report {

    static final String CITATION = "Data: F. J. Ordóñez, P. de Toledo, A. Sanchis, \"Activity Recognition Using Hybrid "
            + "Generative/Discriminative Models on Home Environments Using Binary Sensors\", *Sensors* 2013, 13, "
            + "5460–5477; UCI data set 271, CC BY 4.0, no commercial use (data/ordonez/PROVENANCE.md).";

    private Report() {
    }

    static String markdown(String title, List<String> facts, Map<String, Experiment.Result> results) {
        List<Experiment.Result> rs = new ArrayList<>(results.values());
        StringBuilder b = new StringBuilder("### ").append(title).append("\n\n");
        facts.forEach(f -> b.append("- ").append(f).append('\n'));
        b.append("\n| figure |");
        rs.forEach(r -> b.append(" `detector=").append(r.detector()).append("` |"));
        b.append("\n|---|");
        rs.forEach(r -> b.append("---|"));
        b.append('\n');
        row(b, rs, "false alarms / 30 days, day (07–22)", r -> f1(r.test().perThirtyDays(r.test().alertsDay()))
                + " (" + r.test().alertsDay() + ")");
        row(b, rs, "false alarms / 30 days, night", r -> f1(r.test().perThirtyDays(r.test().alertsNight())) + " ("
                + r.test().alertsNight() + ")");
        row(b, rs, "collapses detected within 12 h", r -> count(r, CollapseResult.Outcome.DETECTED));
        row(b, rs, "— not detected: alert already raised in the quiet period", r -> count(r,
                CollapseResult.Outcome.ALREADY_ALERTED));
        row(b, rs, "— not detected: no alert within 12 h", r -> count(r, CollapseResult.Outcome.MISSED));
        row(b, rs, "median delay, collapses by day", r -> median(r, true));
        row(b, rs, "median delay, collapses by night", r -> median(r, false));
        row(b, rs, "UNOCCUPIED vs labelled Leaving: recall", r -> f3(r.test().occupancy().recall()));
        row(b, rs, "UNOCCUPIED vs labelled Leaving: precision", r -> f3(r.test().occupancy().precision()));
        row(b, rs, "at-home time not watched (blind)", r -> String.format(Locale.ROOT, "%.1f %%",
                100 * r.test().blindShare()));
        row(b, rs, "test-half run: alerts in the test half / alerts handed on (alert service or Mail Manager) / alert mails at the SMTP "
                + "sink (both incl. the restart's, below)", r -> (r.test().alertsDay() + r.test().alertsNight()) + " / "
                + r.handedOver() + " / " + r.mails());
        row(b, rs, "datagrams the kernel dropped at the radio (all runs)", r -> r.kernelDrops() < 0 ? "n/a"
                : Long.toString(r.kernelDrops()));
        row(b, rs, "detector named in the event log", r -> r.testTimeline().detectorLog().isEmpty() ? "(no entry names it)"
                : r.testTimeline().detectorLog().replace("|", "\\|"));
        return b.toString();
    }

    private static void row(StringBuilder b, List<Experiment.Result> rs, String name,
            Function<Experiment.Result, String> f) {
        b.append("| ").append(name).append(" |");
        rs.forEach(r -> b.append(' ').append(f.apply(r)).append(" |"));
        b.append('\n');
    }

    private static String count(Experiment.Result r, CollapseResult.Outcome o) {
        long n = r.collapses().stream().filter(c -> c.outcome() == o).count();
        int all = r.collapses().size();
        return n + " / " + all + (all == 0 ? "" : String.format(Locale.ROOT, " (%.1f %%)", 100.0 * n / all));
    }

    private static String median(Experiment.Result r, boolean day) {
        List<Duration> d = r.collapses().stream()
                .filter(c -> c.outcome() == CollapseResult.Outcome.DETECTED && TestHalfFigures.isDay(c.at()) == day)
                .map(CollapseResult::delay).sorted().toList();
        long all = r.collapses().stream().filter(c -> TestHalfFigures.isDay(c.at()) == day).count();
        if (d.isEmpty()) {
            return "– (0 of " + all + " detected)";
        }
        Duration m = d.size() % 2 == 1 ? d.get(d.size() / 2) : d.get(d.size() / 2 - 1).plus(d.get(d.size() / 2))
                .dividedBy(2);
        return hm(m) + " (" + d.size() + " of " + all + ")";
    }

    static String hm(Duration d) {
        long m = Math.round(d.toSeconds() / 60.0);
        return m >= 60 ? String.format(Locale.ROOT, "%d h %02d min", m / 60, m % 60) : m + " min";
    }

    private static String f1(double v) {
        return String.format(Locale.ROOT, "%.1f", v);
    }

    private static String f3(double v) {
        return Double.isNaN(v) ? "–" : String.format(Locale.ROOT, "%.3f", v);
    }
}
