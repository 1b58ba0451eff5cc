package org.tinysep.simulator.time;

import java.time.Instant;

/** Plays one virtual second. */
@FunctionalInterface
public interface Stepper {

    /** @return how many reported values changed in this second (the driver paces the platform after those) */
    int step(Instant t) throws Exception;
}
