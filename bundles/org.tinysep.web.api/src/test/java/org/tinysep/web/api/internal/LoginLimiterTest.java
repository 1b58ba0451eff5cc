package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.MutableClock;

class LoginLimiterTest {

    private final MutableClock clock = new MutableClock(Instant.parse("2026-11-25T12:00:00Z"));

    @Test
    void aClientIsStoppedAfterTooManyFailuresUntilTheWindowHasPassed() {
        LoginLimiter limiter = new LoginLimiter(3, Duration.ofSeconds(60), clock);
        for (int i = 0; i < 3; i++) {
            assertEquals(Duration.ZERO, limiter.waitFor("10.0.0.1"));
            limiter.failed("10.0.0.1");
            clock.advance(Duration.ofSeconds(1));
        }
        Duration wait = limiter.waitFor("10.0.0.1");
        assertTrue(wait.compareTo(Duration.ofSeconds(57)) == 0, wait.toString());
        assertEquals(Duration.ZERO, limiter.waitFor("10.0.0.2"), "another client may still try");
        clock.advance(Duration.ofSeconds(57));
        assertEquals(Duration.ZERO, limiter.waitFor("10.0.0.1"));
    }

    @Test
    void manyClientsTogetherAreStoppedToo() {
        LoginLimiter limiter = new LoginLimiter(2, Duration.ofSeconds(60), clock);
        for (int i = 0; i < 8; i++) {
            limiter.failed("10.0.0." + i);
        }
        assertTrue(limiter.waitFor("10.0.0.99").toSeconds() > 0);
    }

    @Test
    void successForgetsTheClientsFailures() {
        LoginLimiter limiter = new LoginLimiter(2, Duration.ofSeconds(60), clock);
        limiter.failed("a");
        limiter.succeeded("a");
        limiter.failed("a");
        assertEquals(Duration.ZERO, limiter.waitFor("a"));
    }
}
