package org.tinysep.simulator.time;

import java.time.Instant;
import java.util.List;

/** Plays one virtual second, and what falls due inside it. */
@FunctionalInterface
public interface Stepper {

    /** @return how many reported values changed in this second (the driver paces the platform after those) */
    int step(Instant t) throws Exception;

    /**
     * @return the instants after {@code t} and before the next second at which something more is due (a worn
     *         node's frame inside the second: docs/time-sync.md lets a TICK move the clock by less than a second),
     *         in order; none by default
     */
    default List<Instant> within(Instant t) {
        return List.of();
    }

    /** Sends what is due at {@code at}, one of {@link #within}'s instants. @return as {@link #step} */
    default int stepWithin(Instant at) throws Exception {
        return 0;
    }
}
