package org.tinysep.simulator.time;

import java.time.Instant;

/** A clock that moves only when the driver sets it. */
public final class VirtualClock implements SimClock {

    private volatile Instant now;

    public VirtualClock(Instant start) {
        this.now = start;
    }

    public void set(Instant t) {
        now = t;
    }

    @Override
    public Instant now() {
        return now;
    }
}
