package org.tinysep.evaluation;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/** The core replay's figures as one markdown table (home, model, detector) and a summary row per detector. */
final class CoreTable {

    private CoreTable() {
    }

    static String markdown(List<CoreSweep.Figures> all) {
        StringBuilder b = new StringBuilder("| home | collapse model | detector | false alarms / 30 d (day + night) "
                + "| median delay day / night | p95 delay | detected | blind |\n|---|---|---|---|---|---|---|---|\n");
        for (CoreSweep.Figures f : all) {
            b.append(row(f.home(), f.model(), f)).append('\n');
        }
        for (boolean learned : new boolean[] {true, false}) {
            for (String model : all.stream().map(CoreSweep.Figures::model).distinct().toList()) {
                List<CoreSweep.Figures> of = all.stream().filter(f -> f.learned() == learned
                        && f.model().equals(model)).toList();
                if (of.size() < 2) {
                    continue;
                }
                List<CoreSweep.Figures> byFa = new ArrayList<>(of);
                byFa.sort(Comparator.comparingDouble(f -> f.faDay() + f.faNight()));
                CoreSweep.Figures worst = byFa.get(byFa.size() - 1);
                CoreSweep.Figures median = byFa.get((byFa.size() - 1) / 2);
                b.append(row("**worst home by false alarms** (" + worst.home() + ")", model, worst)).append('\n');
                b.append(row("**median home by false alarms** (" + median.home() + ")", model, median)).append('\n');
                CoreSweep.Figures leastDetected = of.stream().min(Comparator.comparingDouble(
                        CoreSweep.Figures::detected)).orElseThrow();
                b.append(row("**worst home by detection** (" + leastDetected.home() + ")", model, leastDetected))
                        .append('\n');
            }
        }
        return b.toString();
    }

    /** @return the facts line above the table: when, which commit, the exact command, split, collapses, seed */
    static String facts(java.time.Instant when, String commit, String[] args, int k, int n) {
        return "Run " + when + ", commit `" + commit + "`, command `./evaluate.sh " + String.join(" ", args)
                + "` (the detector core, `CoreSweep`; split " + (k > 0 ? "cv" + k : "half: learned from the first half"
                + " of each recording, judged on the second") + "; " + n + " collapses per home, model and detector;"
                + " seed 1). False alarms per 30 days by day (07–22) + night; median delay of the detected collapses"
                + " by the collapse's time of day; blind = share of the drawn collapses that happened while the flat"
                + " counted as empty (not watched).\n";
    }

    private static String row(String home, String model, CoreSweep.Figures f) {
        return String.format(Locale.ROOT, "| %s | %s | %s | %.1f + %.1f | %s / %s | %s | %.1f %% of %d | %.1f %% |", home, model,
                f.learned() ? "LEARNED" : "THESIS", f.faDay(), f.faNight(), hm(f.medianDay()), hm(f.medianNight()),
                hm(f.p95()), f.detected(), f.collapses(), f.blind());
    }

    /** @return minutes as "1 h 05" or "35 min", "–" if none */
    static String hm(Long minutes) {
        if (minutes == null) {
            return "–";
        }
        return minutes < 60 ? minutes + " min" : String.format(Locale.ROOT, "%d h %02d", minutes / 60, minutes % 60);
    }
}
