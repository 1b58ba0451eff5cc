package org.tinysep.falldetection.internal;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.MovementSummary;

/**
 * The wearer's upright, in the node's axes, learned from the node's own summaries: how the node hangs on this
 * person while they walk, not the node's fixed axis (a pendant or a belt clip sits tilted differently on everyone).
 * A summary is evidence of walking when its magnitude SD is at least {@value #MOVING_SD_MG} mg (walking, stairs,
 * jogging: sustained upright movement); {@value #RUN} of them one after the other, each mean within
 * {@value #SAME_DEG}° of the run's first, are one observation of upright (a turn in bed or getting up moves for a
 * moment and through changing postures, so it makes no such run). The upright is the mean of the last
 * {@value #KEEP} observations, so it follows a node that was put on differently. Until the first run it is unknown.
 */
final class Upright {

    static final int MOVING_SD_MG = 100;
    static final int RUN = 3;
    static final double SAME_DEG = 20;
    static final int KEEP = 30;

    private final List<MovementSummary> run = new ArrayList<>();
    private final ArrayDeque<Acceleration> observed = new ArrayDeque<>();
    private Acceleration upright;

    /** One summary, in order. */
    void summary(MovementSummary m) {
        if (m.magnitudeSdMg() < MOVING_SD_MG || m.mean().magnitudeMg() == 0) {
            run.clear();
            return;
        }
        if (!run.isEmpty()) {
            MovementSummary last = run.get(run.size() - 1);
            boolean follows = !m.end().minus(m.span()).isAfter(last.end().plusSeconds(1));
            if (!follows || FallDetector.angle(run.get(0).mean(), m.mean()) > SAME_DEG) {
                run.clear();
            }
        }
        run.add(m);
        if (run.size() == RUN) {
            observed.addLast(Acceleration.mean(run.stream().map(MovementSummary::mean).toList()));
            if (observed.size() > KEEP) {
                observed.removeFirst();
            }
            upright = Acceleration.mean(List.copyOf(observed));
            run.clear();
        }
    }

    /** Starts from an upright known from before, as one observation. */
    void seed(Acceleration known) {
        observed.addLast(known);
        upright = known;
    }

    /** @return the wearer's upright, once the node has seen them walk */
    Optional<Acceleration> get() {
        return Optional.ofNullable(upright);
    }
}
