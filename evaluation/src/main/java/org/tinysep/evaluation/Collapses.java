package org.tinysep.evaluation;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.tinysep.simulator.replay.Evaluation;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.Label;

/**
 * Draws the injected collapses: uniformly (fixed seed) over the test half's time during which the resident is at home
 * and awake per the labels, i.e. outside every {@code Leaving} and {@code Sleeping} label, and within the labelled
 * span (from the first label's start to the last label's end): after the last label nobody says whether the resident
 * is awake or even at home (Ordonez A's labels end at 21:41 on its last evening, its sensors go on until the bed mat
 * turns OFF at 07:22 the next morning), so no collapse is placed there.
 */
final class Collapses {

    private Collapses() {
    }

    /** @return the at-home, awake intervals of {@code [from, to)} within the labelled span */
    static List<Interval> candidates(List<Label> labels, LocalDateTime from, LocalDateTime to) {
        List<Label> valid = labels.stream().filter(Label::isProper).toList();
        LocalDateTime first = valid.stream().map(Label::start).min(LocalDateTime::compareTo).orElse(to);
        LocalDateTime last = valid.stream().map(Label::end).max(LocalDateTime::compareTo).orElse(from);
        LocalDateTime start = first.isAfter(from) ? first : from;
        LocalDateTime end = last.isBefore(to) ? last : to;
        if (!start.isBefore(end)) {
            return List.of();
        }
        List<Interval> excluded = new ArrayList<>(Evaluation.leaving(labels));
        excluded.addAll(Evaluation.intervalsOf(labels, "Sleeping"));
        return Intervals.minus(new Interval(start, end), Evaluation.merge(excluded));
    }

    /** @return {@code n} moments drawn with {@code seed}, in time order (to whole seconds) */
    static List<LocalDateTime> draw(List<Interval> candidates, int n, long seed) {
        long total = candidates.stream().mapToLong(i -> i.length().toSeconds()).sum();
        if (total <= 0) {
            throw new IllegalArgumentException("no at-home, awake time in the test half to place collapses in");
        }
        Random random = new Random(seed);
        List<LocalDateTime> out = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            long s = (long) (random.nextDouble() * total);
            for (Interval i : candidates) {
                long len = i.length().toSeconds();
                if (s < len) {
                    out.add(i.start().plus(Duration.ofSeconds(s)));
                    break;
                }
                s -= len;
            }
        }
        out.sort(null);
        return out;
    }

    /** A collapse model. */
    enum Model {
        /** a moment drawn uniformly over the awake at-home time */
        UNIFORM,
        /** "a fall while moving": at a recorded activity drawn uniformly over the awake at-home events */
        MOVING
    }

    /** How long after the drawn activity a "moving" collapse happens: the quiet period starts at the collapse. */
    static final Duration AFTER_ACTIVITY = Duration.ofSeconds(1);

    /**
     * "A fall while moving": {@code n} recorded activities drawn uniformly (with replacement, seeded) among those
     * that lie in the awake at-home {@code candidates}; each collapse is {@link #AFTER_ACTIVITY} after its activity.
     *
     * @return the collapse moments in time order
     */
    static List<LocalDateTime> drawAtActivities(List<LocalDateTime> activities, List<Interval> candidates, int n,
            long seed) {
        List<LocalDateTime> awake = activities.stream().filter(t -> candidates.stream()
                .anyMatch(i -> !t.isBefore(i.start()) && t.isBefore(i.end()))).toList();
        if (awake.isEmpty()) {
            throw new IllegalArgumentException("no recorded activity at home and awake in the test time to place "
                    + "\"moving\" collapses at");
        }
        Random random = new Random(seed);
        List<LocalDateTime> out = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            out.add(awake.get(random.nextInt(awake.size())).plus(AFTER_ACTIVITY));
        }
        out.sort(null);
        return out;
    }
}
