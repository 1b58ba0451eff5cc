package org.tinysep.device.support.time;

import java.time.Duration;

/**
 * Exponential back-off as a value: after the n-th failure in a row the next attempt waits {@code initial × 2^(n-1)},
 * never more than {@code max}; a success starts again from {@code initial}. Immutable: {@link #failed()} and
 * {@link #reset()} return the next state. The one back-off of the Mail Manager (per message), the MQTT bridge
 * (reconnecting to its broker) and the launcher's supervisor (restarting the platform).
 *
 * @param initial  the wait after the first failure (positive)
 * @param max      the longest wait (at least {@code initial})
 * @param failures failures in a row so far (0: none)
 */
public record Backoff(Duration initial, Duration max, int failures) {

    /** @throws IllegalArgumentException for a wait that is not positive, a maximum below it or negative failures */
    public Backoff {
        if (initial == null || initial.isNegative() || initial.isZero()) {
            throw new IllegalArgumentException("back-off: the first wait must be positive, not " + initial);
        }
        if (max == null || max.compareTo(initial) < 0) {
            throw new IllegalArgumentException("back-off: the longest wait " + max + " is below the first " + initial);
        }
        if (failures < 0) {
            throw new IllegalArgumentException("back-off: failures cannot be negative: " + failures);
        }
    }

    /** @return no failures yet; a {@code max} below {@code initial} is raised to it */
    public static Backoff of(Duration initial, Duration max) {
        return new Backoff(initial, max.compareTo(initial) < 0 ? initial : max, 0);
    }

    /** @return no failures yet, the waits in whole seconds (a maximum below the first wait is raised to it) */
    public static Backoff ofSeconds(long initial, long max) {
        return of(Duration.ofSeconds(initial), Duration.ofSeconds(max));
    }

    /** @return this back-off after one more failure: {@link #delay()} is then the wait before the next attempt */
    public Backoff failed() {
        return new Backoff(initial, max, failures == Integer.MAX_VALUE ? failures : failures + 1);
    }

    /** @return this back-off after a success: no failures */
    public Backoff reset() {
        return failures == 0 ? this : new Backoff(initial, max, 0);
    }

    /** @return the wait before the next attempt: zero before any failure, else doubled per failure up to max */
    public Duration delay() {
        if (failures == 0) {
            return Duration.ZERO;
        }
        Duration d = initial;
        for (int i = 1; i < failures && d.compareTo(max) < 0; i++) {
            d = d.multipliedBy(2);
        }
        return d.compareTo(max) > 0 ? max : d;
    }

    /** @return {@link #delay()} in whole seconds */
    public long delaySeconds() {
        return delay().toSeconds();
    }
}
