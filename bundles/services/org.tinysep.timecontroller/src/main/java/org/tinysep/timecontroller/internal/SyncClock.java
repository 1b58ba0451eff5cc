package org.tinysep.timecontroller.internal;

import java.time.Instant;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Supplier;
import org.tinysep.api.service.ClockMode;

/**
 * The clock's state machine. REAL: the system clock. EXTERNAL: held at an instant that only TICKs move, never
 * backwards. Switching to EXTERNAL holds the clock where it is; switching to REAL returns to the system clock
 * (which may be a jump either way). Thread-safe; pure (the system clock is a parameter).
 */
final class SyncClock {

    enum Outcome {
        /** The clock is now at the tick's instant (later than or equal to before): fire listeners. */
        ADVANCED,
        /** The same sequence number and instant as the last accepted tick: a retransmission, answered again. */
        REPEATED,
        /** Earlier than the current time: refused. */
        BACKWARDS,
        /** The clock is in REAL mode: refused. */
        NOT_EXTERNAL
    }

    /** What a tick did, and the clock's time afterwards. */
    record TickResult(Outcome outcome, Instant now) {
    }

    private final Supplier<Instant> system;
    private ClockMode mode;
    private Instant held;
    private long lastSeq = -1;
    private Instant lastAt;

    SyncClock(Supplier<Instant> system, ClockMode initial) {
        this.system = Objects.requireNonNull(system, "system");
        this.mode = ClockMode.REAL;
        switchTo(initial);
    }

    synchronized Instant now() {
        return mode == ClockMode.REAL ? system.get() : held;
    }

    synchronized ClockMode mode() {
        return mode;
    }

    /**
     * Switches mode.
     *
     * @return the clock's time right after the switch, empty when it already was in that mode
     */
    synchronized Optional<Instant> switchTo(ClockMode next) {
        Objects.requireNonNull(next, "mode");
        if (next == mode) {
            return Optional.empty();
        }
        if (next == ClockMode.EXTERNAL) {
            held = system.get();
        }
        mode = next;
        lastSeq = -1;
        lastAt = null;
        return Optional.of(now());
    }

    /** Applies {@code TICK seq at}. */
    synchronized TickResult tick(long seq, Instant at) {
        Objects.requireNonNull(at, "at");
        if (mode != ClockMode.EXTERNAL) {
            return new TickResult(Outcome.NOT_EXTERNAL, now());
        }
        if (seq == lastSeq && at.equals(lastAt)) {
            return new TickResult(Outcome.REPEATED, held);
        }
        if (at.isBefore(held)) {
            return new TickResult(Outcome.BACKWARDS, held);
        }
        held = at;
        lastSeq = seq;
        lastAt = at;
        return new TickResult(Outcome.ADVANCED, held);
    }
}
