package org.tinysep.simulator.cli;

import java.time.Instant;
import java.util.List;
import org.tinysep.simulator.time.Stepper;

/** Prints the agents' moves as they happen and a progress line every N virtual minutes. */
final class Progress {

    private final Simulation sim;
    private final long everySeconds;
    private final long start;
    private final long wallStart = System.nanoTime();
    private int traced;

    Progress(Simulation sim, int minutes, Instant from) {
        this.sim = sim;
        this.everySeconds = Math.max(1, minutes) * 60L;
        this.start = from.getEpochSecond();
        this.traced = sim.world().trace().size();
    }

    /** @return {@code inner} with the progress printed; what falls due inside a second comes from the simulation */
    Stepper wrap(Stepper inner) {
        return new Stepper() {
            @Override
            public int step(Instant t) throws Exception {
                return stepAndTell(inner, t);
            }

            @Override
            public List<Instant> within(Instant t) {
                return sim.within(t);
            }

            @Override
            public int stepWithin(Instant at) {
                return sim.stepWithin(at);
            }
        };
    }

    private int stepAndTell(Stepper inner, Instant t) throws Exception {
        int changed = inner.step(t);
        List<String> trace = sim.world().trace();
        for (; traced < trace.size(); traced++) {
            System.out.println("  " + trace.get(traced));
        }
        long s = t.getEpochSecond();
        if (s > start && (s - start) % everySeconds == 0) {
            System.out.printf("%s  %.1f s wall  %s%n", t, (System.nanoTime() - wallStart) / 1e9, sim.director().whereabouts());
        }
        return changed;
    }
}
