package org.tinysep.evaluation.falls;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/**
 * The figures of a set of judged recordings: sensitivity (falls alerted within 30 s of the impact), specificity
 * (ADL recordings without any alert), false alerts per hour of ADL recording (the padding not counted), and the
 * delay from the impact to the alert (p50, p95; nearest rank).
 */
record Figures(int falls, int detected, int adls, int quietAdls, int falseAlerts, double adlHours,
        List<Double> delays) {

    static Figures of(List<Scored> scored) {
        int falls = 0;
        int detected = 0;
        int adls = 0;
        int quiet = 0;
        int fa = 0;
        double hours = 0;
        List<Double> delays = new ArrayList<>();
        for (Scored s : scored) {
            if (s.fall()) {
                falls++;
                if (s.delay().isPresent()) {
                    detected++;
                    delays.add(s.delay().get().toMillis() / 1000.0);
                }
            } else {
                adls++;
                quiet += s.alerts().isEmpty() ? 1 : 0;
                fa += s.alerts().size();
                hours += s.stream().recorded().toMillis() / 3_600_000.0;
            }
        }
        Collections.sort(delays);
        return new Figures(falls, detected, adls, quiet, fa, hours, List.copyOf(delays));
    }

    double sensitivity() {
        return falls == 0 ? Double.NaN : 100.0 * detected / falls;
    }

    double specificity() {
        return adls == 0 ? Double.NaN : 100.0 * quietAdls / adls;
    }

    double falseAlertsPerHour() {
        return adlHours == 0 ? Double.NaN : falseAlerts / adlHours;
    }

    double delay(double p) {
        if (delays.isEmpty()) {
            return Double.NaN;
        }
        int rank = (int) Math.ceil(p * delays.size());
        return delays.get(Math.max(0, Math.min(delays.size() - 1, rank - 1)));
    }

    /** @return sensitivity + specificity, the LOSO folds' objective (NaN parts count as 100) */
    double balanced() {
        double se = falls == 0 ? 100 : sensitivity();
        double sp = adls == 0 ? 100 : specificity();
        return se + sp;
    }

    /** @return one table row: subject | falls | sensitivity | ADLs | specificity | FA/h | p50 | p95 */
    String row(String name) {
        return String.format(Locale.ROOT, "| %s | %d/%d | %s | %d/%d | %s | %s | %s | %s |", name, detected, falls,
                pct(sensitivity()), quietAdls, adls, pct(specificity()), num(falseAlertsPerHour(), 2),
                num(delay(0.5), 1), num(delay(0.95), 1));
    }

    /** @return the line scripts read */
    String lastLine() {
        return String.format(Locale.ROOT, "falls: sensitivity %s %%, specificity %s %%, false alerts per ADL hour %s,"
                + " delay p50 %s s, p95 %s s", num(sensitivity(), 1), num(specificity(), 1),
                num(falseAlertsPerHour(), 2), num(delay(0.5), 1), num(delay(0.95), 1));
    }

    static String pct(double v) {
        return Double.isNaN(v) ? "–" : String.format(Locale.ROOT, "%.1f %%", v);
    }

    static String num(double v, int digits) {
        return Double.isNaN(v) ? "n/a" : String.format(Locale.ROOT, "%." + digits + "f", v);
    }

}
