package org.tinysep.evaluation;

import java.time.Duration;
import java.time.Instant;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@link CoreSweep}'s collapse judging: replays the window before each collapse on the learned history and counts it
 * detected (the first alert within 12 h after it, with its delay by the collapse's time of day), already alerted (an
 * alert in its quiet period before it), missed, and blind (the flat counted as empty at the collapse).
 */
final class CoreCollapses {

    private final boolean verbose;
    private int detected;
    private int already;
    private int missed;
    private int blind;
    private final List<Long> dayDelays = new ArrayList<>();
    private final List<Long> nightDelays = new ArrayList<>();

    CoreCollapses(boolean verbose) {
        this.verbose = verbose;
    }

    /**
     * @param everything the whole recording's activities
     * @param hist       the fold's history
     * @param cv         a cross-validation fold (its history is used whole; else only what lies before the collapse)
     * @param c          the collapse
     */
    void judge(CoreReplay core, List<CoreReplay.Act> everything, List<CoreReplay.Act> hist, boolean cv,
            LocalDateTime c) {
        Instant ci = CoreReplay.at(c);
        List<CoreReplay.Act> before = everything.stream().filter(a -> a.at().isBefore(ci)
                && !a.at().isBefore(ci.minus(Duration.ofHours(6)))).toList();
        if (before.isEmpty()) {
            before = everything.stream().filter(a -> a.at().isBefore(ci)).toList();
            before = before.subList(Math.max(0, before.size() - 1), before.size());
        }
        if (before.isEmpty()) {
            return;
        }
        List<CoreReplay.Act> histBefore = cv ? hist : hist.stream().filter(a -> a.at().isBefore(ci)).toList();
        // the collapsing resident's events after the moment are deleted; a second resident's stay
        List<CoreReplay.Act> acts = new ArrayList<>(before);
        everything.stream().filter(x -> x.what().startsWith("second resident's ") && x.at().isAfter(ci)
                && !x.at().isAfter(ci.plus(Duration.ofHours(12)))).forEach(acts::add);
        blind += CoreReplay.blindAt(acts, ci) ? 1 : 0;
        var fresh = core.newLimits();
        core.play(fresh, histBefore, t -> false);
        List<CoreReplay.Alert> alerts = core.play(fresh, acts, t -> true);
        CoreReplay.Act last = before.get(before.size() - 1);
        CoreReplay.Alert early = alerts.stream().filter(x -> !x.at().isBefore(last.at())
                && !x.at().isAfter(ci)).findFirst().orElse(null);
        CoreReplay.Alert a = alerts.stream().filter(x -> x.at().isAfter(ci)
                && !x.at().isAfter(ci.plus(Duration.ofHours(12)))).findFirst().orElse(null);
        if (early != null) {
            already++;
            if (verbose) {
                System.out.printf("  ALREADY %s: quiet since %s after %s in %s, limit %s, alert %s%n", c,
                        early.after().at(), early.after().what(), early.after().room(), early.limit(), early.at());
            }
        } else if (a == null) {
            missed++;
            if (verbose) {
                System.out.printf("  MISSED %s after %s in %s%n", c, last.what(), last.room());
            }
        } else {
            detected++;
            if (verbose) {
                System.out.printf("  DETECTED %s after %d min: quiet since %s after %s in %s, limit %s; %s%n",
                        c, Duration.between(ci, a.at()).toMinutes(), a.after().at(), a.after().what(),
                        a.after().room(), a.limit(), a.why());
            }
            int h = c.getHour();
            (h < 7 || h >= 22 ? nightDelays : dayDelays).add(Duration.between(ci, a.at()).toMinutes());
        }
    }

    int total() {
        return detected + already + missed;
    }

    double detectedShare() {
        return total() == 0 ? 0 : 100.0 * detected / total();
    }

    double blindShare() {
        return total() == 0 ? 0 : 100.0 * blind / total();
    }

    Long medianDay() {
        return median(dayDelays);
    }

    Long medianNight() {
        return median(nightDelays);
    }

    /** @return the 95th percentile of all delays (nearest rank), or null */
    Long p95() {
        List<Long> all = new ArrayList<>(dayDelays);
        all.addAll(nightDelays);
        all.sort(null);
        return all.isEmpty() ? null : all.get(Math.min(all.size() - 1, (int) Math.ceil(0.95 * all.size()) - 1));
    }

    private static Long median(List<Long> v) {
        if (v.isEmpty()) {
            return null;
        }
        List<Long> s = new ArrayList<>(v);
        s.sort(null);
        return s.get(s.size() / 2);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "collapses: detected %d/%d (%.1f %%), already alerted %d, missed %d; median "
                + "delay day %s min night %s min; blind at %d (%.1f %%)", detected, total(), detectedShare(), already,
                missed, medianDay(), medianNight(), blind, blindShare());
    }
}
