package org.tinysep.evaluation;

import java.time.LocalDate;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * How a recording is divided into history (learned from) and test (judged), as folds.
 * <ul>
 * <li>{@code half} (the headline): one fold, history = the first half, test = the second.</li>
 * <li>{@code cvK}: K folds by days; day i of the recording (counted from its first day) is tested in fold i mod K and
 * is history in every other fold, so every day is tested once and learned from in K−1 folds (cv with K = number of
 * days is leave-one-day-out). The test days are replayed {@link Fold#extraDays} later than recorded (whole weeks,
 * after the end of the recording), since a platform's clock only moves forward.</li>
 * </ul>
 */
record Split(String name, List<Fold> folds) {

    /**
     * One fold.
     *
     * @param index     0..K−1
     * @param history   the events learned from (replayed into the snapshot), in time order
     * @param spans     the recorded time judged (test days, clipped to the recording)
     * @param extraDays how much later than recorded the test is replayed (whole weeks; 0 for {@code half})
     */
    record Fold(int index, List<SensorEvent> history, List<Interval> spans, long extraDays) {
        boolean covers(LocalDateTime t) {
            return spans.stream().anyMatch(s -> !t.isBefore(s.start()) && t.isBefore(s.end()));
        }
    }

    static Split of(String spec, Home home) {
        if (spec.equals("half")) {
            LocalDateTime s = home.split();
            return new Split("half", List.of(new Fold(0, home.events().stream().filter(e -> e.time().isBefore(s))
                    .toList(), List.of(new Interval(s, after(home))), 0)));
        }
        if (!spec.matches("cv[1-9][0-9]*")) {
            throw new IllegalArgumentException("--split must be half or cvK (e.g. cv7), not '" + spec + "'");
        }
        int k = Integer.parseInt(spec.substring(2));
        LocalDateTime start = home.events().get(0).time();
        LocalDate first = start.toLocalDate();
        int days = (int) (home.end().toLocalDate().toEpochDay() - first.toEpochDay()) + 1;
        if (k < 2 || k > days) {
            throw new IllegalArgumentException("--split cvK needs 2 <= K <= " + days + " (the recording's days)");
        }
        long extra = (days + 1 + 6) / 7 * 7L;
        List<Fold> folds = new ArrayList<>();
        for (int f = 0; f < k; f++) {
            List<Interval> spans = new ArrayList<>();
            for (int i = f; i < days; i += k) {
                LocalDateTime a = first.plusDays(i).atStartOfDay();
                LocalDateTime b = a.plusDays(1);
                spans.add(new Interval(a.isBefore(start) ? start : a, b.isAfter(home.end()) ? after(home) : b));
            }
            Fold probe = new Fold(f, List.of(), spans, extra);
            folds.add(new Fold(f, home.events().stream().filter(e -> !probe.covers(e.time())).toList(), spans, extra));
        }
        return new Split(spec, folds);
    }

    /** A test segment: the events replayed and the recorded time judged (from its first event). */
    record TestSegment(List<SensorEvent> events, Interval judged) {
    }

    /**
     * @return the test segments of a fold, one per span: its events, plus (cv) the recording's next event after it,
     *         so the quiet period at the span's end ends when the recorded one did; judged from the span's first
     *         event (before it a restarted platform's clock jump raises an alert that is not the resident's)
     */
    static List<TestSegment> testSegments(Home home, Fold fold) {
        List<TestSegment> out = new ArrayList<>();
        for (Interval s : fold.spans()) {
            List<SensorEvent> seg = new ArrayList<>();
            for (SensorEvent e : home.events()) {
                if (!e.time().isBefore(s.start()) && e.time().isBefore(s.end())) {
                    seg.add(e);
                } else if (!e.time().isBefore(s.end())) {
                    if (!seg.isEmpty() && fold.extraDays() > 0) {
                        seg.add(e);
                    }
                    break;
                }
            }
            if (!seg.isEmpty()) {
                LocalDateTime end = fold.extraDays() > 0 ? s.end() : after(home);
                out.add(new TestSegment(seg, new Interval(seg.get(0).time(), end)));
            }
        }
        return out;
    }

    /** @return just after the recording's last event: spans are half-open, and the last event is tested too */
    private static LocalDateTime after(Home home) {
        return home.end().plusSeconds(1);
    }

    /** @return the fold that tests recorded time {@code t}, or null */
    Fold foldOf(LocalDateTime t) {
        return folds.stream().filter(f -> f.covers(t)).findFirst().orElse(null);
    }

    /** @return every fold's judged time */
    List<Interval> spans() {
        return folds.stream().flatMap(f -> f.spans().stream()).toList();
    }
}
