package org.tinysep.simulator.time;

import java.time.Instant;

/**
 * Real time: virtual second {@code t} is played when the wall clock reaches
 * {@code start + (t - from) / speed}; speed 1 is real time, 60 plays a minute a second. If the simulation falls
 * behind it plays the late seconds at once (it never skips). What falls due inside a second ({@link Stepper#within})
 * is played at its own instant.
 */
public final class RealTimeDriver {

    private final VirtualClock clock;
    private final double speed;

    public RealTimeDriver(VirtualClock clock, double speed) {
        if (!(speed > 0)) {
            throw new IllegalArgumentException("speed must be > 0, not " + speed);
        }
        this.clock = clock;
        this.speed = speed;
    }

    public void run(Instant from, Instant until, Stepper stepper) throws Exception {
        long start = System.nanoTime();
        for (Instant t = from; t.isBefore(until); t = t.plusSeconds(1)) {
            long due = start + (long) ((t.getEpochSecond() - from.getEpochSecond()) * 1e9 / speed);
            long wait = due - System.nanoTime();
            if (wait > 0) {
                Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
            }
            clock.set(t);
            stepper.step(t);
            Instant after = t;
            for (Instant in : stepper.within(t)) { // due inside this second: sent at their own instant
                if (!in.isAfter(after) || !in.isBefore(t.plusSeconds(1))) {
                    continue;
                }
                after = in;
                long at = start + (long) (java.time.Duration.between(from, in).toNanos() / speed);
                long w = at - System.nanoTime();
                if (w > 0) {
                    Thread.sleep(w / 1_000_000, (int) (w % 1_000_000));
                }
                clock.set(in);
                stepper.stepWithin(in);
            }
        }
    }
}
