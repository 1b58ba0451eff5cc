package org.tinysep.simulator.time;

import java.time.Instant;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * The one lock-step loop of the simulator, for scenarios and replays (docs/time-sync.md): per played second it sets
 * the simulation's clock, TICKs the platform to that second and waits for DONE, then sends that second's frames
 * (the bus radio stamps them with that second); if any reported value changed it pauses {@code paceNanos} before the
 * next TICK so the radio has processed them ("pace" in time-sync.md: nearly always enough on one machine, not a
 * guarantee under heavy load). Which second is played next is the caller's {@link NextSecond}: every second for a
 * scenario (the reed switch reports every second), the next second with something to send for a replay.
 */
public final class LockStepDriver {

    /** The next second to play after a played one (epoch seconds, greater than {@code t}). */
    @FunctionalInterface
    public interface NextSecond {
        long after(long t);
    }

    /** Every second is played. */
    public static final NextSecond EVERY_SECOND = t -> t + 1;

    private final SyncClient sync;
    private final VirtualClock clock;
    private final long paceNanos;

    public LockStepDriver(SyncClient sync, VirtualClock clock, long paceNanos) {
        this.sync = sync;
        this.clock = clock;
        this.paceNanos = paceNanos;
    }

    /** Plays every second from {@code from} (inclusive) to {@code until} (exclusive). @return seconds played */
    public long run(Instant from, Instant until, Stepper stepper) throws Exception {
        return run(from, until, stepper, EVERY_SECOND);
    }

    /**
     * Plays the given instants in order, milliseconds kept (a TICK may move the clock by less than a second,
     * docs/time-sync.md): per instant the clock is set, the platform TICKed to it, then {@code stepper} sends what is
     * due then (the bus radio stamps it with that instant). Instants not later than the one before are skipped.
     *
     * @return instants played
     */
    public long runInstants(List<Instant> instants, Stepper stepper) throws Exception {
        long played = 0;
        Instant before = null;
        for (Instant at : instants) {
            if (before != null && !at.isAfter(before)) {
                continue;
            }
            before = at;
            clock.set(at);
            sync.tick(at);
            played++;
            if (stepper.step(at) > 0 && paceNanos > 0) {
                LockSupport.parkNanos(paceNanos);
            }
        }
        return played;
    }

    /**
     * Plays the seconds from {@code from} (inclusive) to {@code until} (exclusive) chosen by {@code next}; after each,
     * the instants inside it that the stepper has something due at ({@link Stepper#within}), each TICKed as it is,
     * milliseconds kept (a worn node's burst leaves at its trigger, not at the whole second).
     *
     * @return TICKs played
     */
    public long run(Instant from, Instant until, Stepper stepper, NextSecond next) throws Exception {
        long played = 0;
        for (long t = from.getEpochSecond(); t < until.getEpochSecond(); t = next.after(t)) {
            Instant at = Instant.ofEpochSecond(t);
            clock.set(at);
            sync.tick(at);
            played++;
            if (stepper.step(at) > 0 && paceNanos > 0) {
                LockSupport.parkNanos(paceNanos);
            }
            Instant after = at;
            for (Instant in : stepper.within(at)) {
                if (!in.isAfter(after) || !in.isBefore(at.plusSeconds(1))) {
                    continue;
                }
                after = in;
                clock.set(in);
                sync.tick(in);
                played++;
                if (stepper.stepWithin(in) > 0 && paceNanos > 0) {
                    LockSupport.parkNanos(paceNanos);
                }
            }
        }
        return played;
    }
}
