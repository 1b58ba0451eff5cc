package org.tinysep.mailmanager.internal;

/** Exponential back-off: the initial delay, doubled after each further failure, never above the maximum. */
final class Backoff {

    private final long initialSeconds;
    private final long maxSeconds;
    private int failures;

    Backoff(long initialSeconds, long maxSeconds) {
        this.initialSeconds = initialSeconds;
        this.maxSeconds = Math.max(initialSeconds, maxSeconds);
    }

    /** Records one more failure. @return the delay before the next attempt, in seconds */
    long fail() {
        failures++;
        long delay = initialSeconds;
        for (int i = 1; i < failures && delay < maxSeconds; i++) {
            delay *= 2;
        }
        return Math.min(delay, maxSeconds);
    }

    /** Forgets the failures after a success. */
    void reset() {
        failures = 0;
    }

    int failures() {
        return failures;
    }
}
