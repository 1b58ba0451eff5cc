package org.tinysep.simulator.cli;

import java.time.Instant;

/** Prints a replay's progress line every {@code --progress-minutes} of virtual time. */
final class ReplayProgress {

    private final Replay replay;
    private final long every;
    private long next;

    ReplayProgress(Replay replay, int minutes, Instant from) {
        this.replay = replay;
        this.every = Math.max(1, minutes) * 60L;
        this.next = from.getEpochSecond() + every;
    }

    void report(Instant at, int sent, long wallStartNanos) {
        long t = at.getEpochSecond();
        if (t < next) {
            return;
        }
        System.out.printf("%s (recorded %s)  %d/%d events  %.1f s wall%n", at, replay.recordedTime(at), sent,
                replay.plan().actions().size(), (System.nanoTime() - wallStartNanos) / 1e9);
        next += every * ((t - next) / every + 1);
    }
}
