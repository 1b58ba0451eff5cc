package org.tinysep.simulator.replay;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.Objects;
import java.util.TreeMap;

/** Pure helpers for comparing what the platform concluded with a recording's labels. */
public final class Evaluation {

    private Evaluation() {
    }

    /**
     * @param labels   labels of a recording
     * @param activity activity name, case-insensitive, e.g. {@code Leaving}
     * @return the proper (end after start) intervals of that activity, merged; improper labels are skipped
     */
    public static List<Interval> intervalsOf(List<Label> labels, String activity) {
        List<Interval> out = new ArrayList<>();
        for (Label l : labels) {
            if (l.activity().equalsIgnoreCase(activity) && l.isProper()) {
                out.add(new Interval(l.start(), l.end()));
            }
        }
        return merge(out);
    }

    /** @return the "Leaving" intervals of the labels, merged */
    public static List<Interval> leaving(List<Label> labels) {
        return intervalsOf(labels, "Leaving");
    }

    /**
     * @param changes state timeline: time → state entered then (e.g. Flat Occupancy changes)
     * @param state   the state of interest
     * @param end     end of observation; the last state lasts until then
     * @return the merged intervals during which the timeline was in {@code state}, up to {@code end}
     */
    public static <S> List<Interval> whileIn(NavigableMap<LocalDateTime, S> changes, S state, LocalDateTime end) {
        List<Interval> out = new ArrayList<>();
        for (Map.Entry<LocalDateTime, S> e : changes.entrySet()) {
            if (Objects.equals(e.getValue(), state) && e.getKey().isBefore(end)) {
                LocalDateTime next = changes.higherKey(e.getKey());
                out.add(new Interval(e.getKey(), next == null || next.isAfter(end) ? end : next));
            }
        }
        return merge(out);
    }

    /** @return the intervals cut to {@code [from, to)}, empty pieces dropped, merged */
    public static List<Interval> clip(List<Interval> intervals, LocalDateTime from, LocalDateTime to) {
        List<Interval> out = new ArrayList<>();
        for (Interval i : intervals) {
            LocalDateTime s = i.start().isBefore(from) ? from : i.start();
            LocalDateTime e = i.end().isAfter(to) ? to : i.end();
            if (s.isBefore(e)) {
                out.add(new Interval(s, e));
            }
        }
        return merge(out);
    }

    /** @return the union of the intervals as sorted, disjoint, non-touching intervals; empty ones dropped */
    public static List<Interval> merge(List<Interval> intervals) {
        List<Interval> sorted = new ArrayList<>(intervals);
        sorted.sort(Comparator.comparing(Interval::start));
        List<Interval> out = new ArrayList<>();
        for (Interval i : sorted) {
            if (!i.start().isBefore(i.end())) {
                continue;
            }
            Interval last = out.isEmpty() ? null : out.get(out.size() - 1);
            if (last != null && !i.start().isAfter(last.end())) {
                out.set(out.size() - 1, new Interval(last.start(), i.end().isAfter(last.end()) ? i.end() : last.end()));
            } else {
                out.add(i);
            }
        }
        return out;
    }

    /**
     * @param reference e.g. labelled Leaving intervals
     * @param predicted e.g. UNOCCUPIED intervals
     * @return overlap agreement of the merged lists
     */
    public static Agreement agreement(List<Interval> reference, List<Interval> predicted) {
        List<Interval> r = merge(reference);
        List<Interval> p = merge(predicted);
        Duration overlap = Duration.ZERO;
        int j = 0;
        for (Interval a : r) {
            while (j < p.size() && !p.get(j).end().isAfter(a.start())) {
                j++;
            }
            for (int k = j; k < p.size() && p.get(k).start().isBefore(a.end()); k++) {
                LocalDateTime s = later(a.start(), p.get(k).start());
                LocalDateTime e = a.end().isBefore(p.get(k).end()) ? a.end() : p.get(k).end();
                overlap = overlap.plus(Duration.between(s, e));
            }
        }
        return new Agreement(total(r), total(p), overlap);
    }

    /** @return ON events (= recorded intervals) per sensor, sorted by sensor name */
    public static NavigableMap<String, Integer> onCountsPerSensor(List<SensorEvent> events) {
        NavigableMap<String, Integer> counts = new TreeMap<>();
        events.stream().filter(SensorEvent::on).forEach(e -> counts.merge(e.sensor(), 1, Integer::sum));
        return counts;
    }

    private static Duration total(List<Interval> intervals) {
        return intervals.stream().map(Interval::length).reduce(Duration.ZERO, Duration::plus);
    }

    private static LocalDateTime later(LocalDateTime a, LocalDateTime b) {
        return a.isAfter(b) ? a : b;
    }
}
