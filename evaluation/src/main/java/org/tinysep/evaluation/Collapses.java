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
 * and awake per the labels, i.e. outside every {@code Leaving} and {@code Sleeping} label.
 */
final class Collapses {

    private Collapses() {
    }

    /** @return the at-home, awake intervals of {@code [from, to)} */
    static List<Interval> candidates(List<Label> labels, LocalDateTime from, LocalDateTime to) {
        List<Interval> excluded = new ArrayList<>(Evaluation.leaving(labels));
        excluded.addAll(Evaluation.intervalsOf(labels, "Sleeping"));
        return Intervals.minus(new Interval(from, to), Evaluation.merge(excluded));
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
}
