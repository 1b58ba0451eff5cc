package org.tinysep.evaluation;

import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * History and test events of one split of a recording for {@link CoreSweep}: the half split or one of k folds by days.
 */
record CoreFold(List<SensorEvent> history, List<SensorEvent> test, List<LocalDate> testDays, boolean cv,
        LocalDateTime from, LocalDateTime to, double share, LocalDateTime end) {
    double days() {
        if (!cv) {
            return Duration.between(from, to).toSeconds() / 86400.0;
        }
        double d = 0;
        for (LocalDate day : testDays) {
            LocalDateTime a = day.atStartOfDay().isBefore(from) ? from : day.atStartOfDay();
            LocalDateTime b = day.plusDays(1).atStartOfDay().isAfter(to) ? to : day.plusDays(1).atStartOfDay();
            d += Math.max(0, Duration.between(a, b).toSeconds()) / 86400.0;
        }
        return d;
    }

    boolean judged(Instant t) {
        LocalDateTime l = LocalDateTime.ofInstant(t, ZoneOffset.UTC);
        return cv ? testDays.contains(l.toLocalDate()) && !l.isAfter(end) : !l.isBefore(from) && !l.isAfter(to);
    }

    List<Interval> candidates(Home h) {
        List<Interval> out = new ArrayList<>();
        if (!cv) {
            return Collapses.candidates(h.labels(), from, to);
        }
        for (LocalDate d : testDays) {
            LocalDateTime e = d.plusDays(1).atStartOfDay();
            out.addAll(Collapses.candidates(h.labels(), d.atStartOfDay(), e.isAfter(end) ? end : e));
        }
        return out;
    }

    static CoreFold half(Home h) {
        LocalDateTime s = h.split();
        return new CoreFold(h.events().stream().filter(e -> e.time().isBefore(s)).toList(),
                h.events().stream().filter(e -> !e.time().isBefore(s)).toList(), List.of(), false, s, h.end(), 1, h.end());
    }

    /** Day i of the recording is tested in fold i mod k and learned from in every other fold. */
    static List<CoreFold> cv(Home h, int k) {
        LocalDate first = h.events().get(0).time().toLocalDate();
        LocalDate last = h.end().toLocalDate();
        int all = (int) (last.toEpochDay() - first.toEpochDay()) + 1;
        List<CoreFold> folds = new ArrayList<>();
        for (int f = 0; f < k; f++) {
            List<LocalDate> days = new ArrayList<>();
            for (int i = f; i < all; i += k) {
                days.add(first.plusDays(i));
            }
            folds.add(new CoreFold(h.events().stream().filter(e -> !days.contains(e.time().toLocalDate())).toList(),
                    h.events().stream().filter(e -> days.contains(e.time().toLocalDate())).toList(), days, true,
                    h.events().get(0).time(), h.end(), (double) days.size() / all, h.end()));
        }
        return folds;
    }
}
