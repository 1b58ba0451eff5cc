package org.tinysep.simulator.time;

import java.time.Instant;
import java.util.concurrent.locks.LockSupport;

/**
 * Lock-step with the platform's Time Controller (docs/time-sync.md): per virtual second, the simulation sends that
 * second's frames, then, if any reported value changed, pauses {@code paceNanos} so the bus radio has processed
 * them ("pace" in time-sync.md: nearly always enough on one machine, not a guarantee under heavy load; a repeated,
 * unchanged status stamped one second late does no harm, so unchanged seconds are not paced), then TICKs and waits
 * for DONE. Every second is ticked: the reed switch reports every second, so no second is idle.
 */
public final class LockStepDriver {

    private final SyncClient sync;
    private final VirtualClock clock;
    private final long paceNanos;

    public LockStepDriver(SyncClient sync, VirtualClock clock, long paceNanos) {
        this.sync = sync;
        this.clock = clock;
        this.paceNanos = paceNanos;
    }

    /** Runs the seconds from {@code from} (inclusive) to {@code until} (exclusive). */
    public void run(Instant from, Instant until, Stepper stepper) throws Exception {
        for (Instant t = from; t.isBefore(until); t = t.plusSeconds(1)) {
            clock.set(t);
            if (stepper.step(t) > 0 && paceNanos > 0) {
                LockSupport.parkNanos(paceNanos);
            }
            sync.tick(t);
        }
    }
}
