package org.tinysep.device.support.time;

import java.time.Instant;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Whether a tick reaches its component: only when what it {@linkplain Due asked for} is due, when it was
 * {@linkplain #wake woken} for an earlier time, or when the clock went back or changed mode (virtual time then real
 * time: the component's own times are re-based at that tick). Ticks are serialised by the caller; {@link #wake} may
 * come from any thread, also during a tick (a wake-up then is never lost).
 */
final class TickGate {

    /** The due time of "every tick" and of the first tick. */
    private static final Instant ALWAYS = Instant.MIN;

    private final Due due;
    /** When the component next needs a tick; null: not until woken. */
    private final AtomicReference<Instant> next = new AtomicReference<>(ALWAYS);
    private Instant last;
    private long calls;

    TickGate(Due due) {
        this.due = due;
    }

    /** One tick of the platform clock: calls the component when it is due. Not concurrent with itself. */
    void tick(Instant now) {
        Instant wanted = next.get();
        boolean back = last != null && now.isBefore(last);
        last = now;
        if (!back && (wanted == null || now.isBefore(wanted))) {
            return;
        }
        next.set(null); // wake-ups during the call are kept beside what the call returns
        calls++;
        Instant asked = ALWAYS;
        try {
            asked = due.tick(now);
        } finally {
            wake(asked);
        }
    }

    /** Something became due at {@code at} (e.g. an event started a timer): the first tick at or after it calls. */
    void wake(Instant at) {
        if (at != null) {
            next.accumulateAndGet(at, Due::earliest);
        }
    }

    /** The next tick calls the component, whatever it asked (the clock switched mode, its settings changed). */
    void next() {
        wake(ALWAYS);
    }

    /** @return ticks that reached the component (for tests: work per tick) */
    long calls() {
        return calls;
    }
}
