package org.tinysep.evaluation;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.simulator.replay.Evaluation;
import org.tinysep.simulator.replay.Interval;

/** Interval arithmetic the simulator's {@link Evaluation} does not have: difference and total length. */
final class Intervals {

    private Intervals() {
    }

    /** @return {@code whole} without the (merged, sorted) {@code holes} */
    static List<Interval> minus(Interval whole, List<Interval> holes) {
        List<Interval> out = new ArrayList<>();
        LocalDateTime at = whole.start();
        for (Interval h : Evaluation.merge(holes)) {
            if (!h.end().isAfter(at) || !h.start().isBefore(whole.end())) {
                continue;
            }
            if (h.start().isAfter(at)) {
                out.add(new Interval(at, h.start()));
            }
            at = h.end().isAfter(at) ? h.end() : at;
        }
        if (at.isBefore(whole.end())) {
            out.add(new Interval(at, whole.end()));
        }
        return out;
    }

    static Duration total(List<Interval> intervals) {
        return Evaluation.merge(intervals).stream().map(Interval::length).reduce(Duration.ZERO, Duration::plus);
    }
}
