package org.tinysep.simulator.time;

import java.time.Instant;

/** The simulation's time: what second the simulated flat is living. */
public interface SimClock {

    Instant now();
}
