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
        int day = 0;
        int night = 0;
        for (LocalDateTime a : t.alerts()) {
            if (!a.isBefore(from) && !a.isAfter(to)) {
                if (isDay(a)) {
                    day++;
                } else {
                    night++;
                }
            }
        }
        List<Interval> leaving = Evaluation.clip(Evaluation.leaving(labels), from, to);
        List<Interval> away = Evaluation.clip(Evaluation.whileIn(t.occupancy(), "UNOCCUPIED", to), from, to);
        List<Interval> atHome = Intervals.minus(new Interval(from, to), leaving);
        List<Interval> blind = Evaluation.clip(Evaluation.whileIn(t.watching(), false, to), from, to);
        Duration home = Intervals.total(atHome);
        Duration blindAtHome = Evaluation.agreement(atHome, blind).overlap();
        return new TestHalfFigures(day, night, Duration.between(from, to).toSeconds() / 86400.0,
                Evaluation.agreement(leaving, away), home.isZero() ? 0 : (double) blindAtHome.toSeconds() / home.toSeconds(),
                home);
    }

    /** Day is 07:00 to 22:00, night the rest (DESIGN.md "Judging the alert"). */
    static boolean isDay(LocalDateTime t) {
        int h = t.getHour();
        return h >= 7 && h < 22;
    }

    double perThirtyDays(int n) {
        return days <= 0 ? 0 : n * 30.0 / days;
    }
}
