package org.tinysep.evaluation;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.List;
import org.tinysep.simulator.replay.Agreement;
import org.tinysep.simulator.replay.Evaluation;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.Label;

/**
 * The figures of the unmodified test half (normal life): false alarms by day (07–22) and night, per 30 days of the
 * test half; Flat Occupancy's UNOCCUPIED against the labelled Leaving time; the share of labelled at-home time the
 * platform was not watching.
 */
record TestHalfFigures(int alertsDay, int alertsNight, double days, Agreement occupancy, double blindShare,
        Duration atHome) {

    static TestHalfFigures of(Timeline t, List<Label> labels, LocalDateTime from, LocalDateTime to) {
        return of(t, labels, List.of(new Interval(from, to)));
    }

    /** The figures over several judged spans of one run (disjoint, in time order): a fold of a cross-validation. */
    static TestHalfFigures of(Timeline t, List<Label> labels, List<Interval> spans) {
        int day = 0;
        int night = 0;
        double days = 0;
        List<Interval> leaving = new java.util.ArrayList<>();
        List<Interval> away = new java.util.ArrayList<>();
        List<Interval> atHome = new java.util.ArrayList<>();
        List<Interval> blind = new java.util.ArrayList<>();
        for (Interval s : spans) {
            LocalDateTime from = s.start();
            LocalDateTime to = s.end();
            for (LocalDateTime a : t.alerts()) {
                if (!a.isBefore(from) && !a.isAfter(to)) {
                    if (isDay(a)) {
                        day++;
                    } else {
                        night++;
                    }
                }
            }
            List<Interval> l = Evaluation.clip(Evaluation.leaving(labels), from, to);
            leaving.addAll(l);
            away.addAll(Evaluation.clip(Evaluation.whileIn(t.occupancy(), "UNOCCUPIED", to), from, to));
            atHome.addAll(Intervals.minus(new Interval(from, to), l));
            blind.addAll(Evaluation.clip(Evaluation.whileIn(t.watching(), false, to), from, to));
            days += Duration.between(from, to).toSeconds() / 86400.0;
        }
        Duration home = Intervals.total(atHome);
        Duration blindAtHome = Evaluation.agreement(atHome, blind).overlap();
        return new TestHalfFigures(day, night, days, Evaluation.agreement(leaving, away),
                home.isZero() ? 0 : (double) blindAtHome.toSeconds() / home.toSeconds(), home);
    }

    /** @return the figures of several folds together (counts and times summed, blind share weighted by time) */
    static TestHalfFigures sum(List<TestHalfFigures> parts) {
        int day = 0;
        int night = 0;
        double days = 0;
        Duration ref = Duration.ZERO;
        Duration pred = Duration.ZERO;
        Duration overlap = Duration.ZERO;
        Duration home = Duration.ZERO;
        double blind = 0;
        for (TestHalfFigures p : parts) {
            day += p.alertsDay();
            night += p.alertsNight();
            days += p.days();
            ref = ref.plus(p.occupancy().reference());
            pred = pred.plus(p.occupancy().predicted());
            overlap = overlap.plus(p.occupancy().overlap());
            home = home.plus(p.atHome());
            blind += p.blindShare() * p.atHome().toSeconds();
        }
        return new TestHalfFigures(day, night, days, new org.tinysep.simulator.replay.Agreement(ref, pred, overlap),
                home.isZero() ? 0 : blind / home.toSeconds(), home);
    }

    /** Day is 07:00 to 22:00, night the rest (evaluation/README.md "What is counted, and how"). */
    static boolean isDay(LocalDateTime t) {
        int h = t.getHour();
        return h >= 7 && h < 22;
    }

    double perThirtyDays(int n) {
        return days <= 0 ? 0 : n * 30.0 / days;
    }
}
