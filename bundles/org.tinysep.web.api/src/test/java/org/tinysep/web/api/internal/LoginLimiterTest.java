package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

class LoginLimiterTest {

    private final MutableClock clock = new MutableClock();

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

    static final class MutableClock extends Clock {
        private Instant now = Instant.parse("2026-11-25T12:00:00Z");

        void advance(Duration d) {
            now = now.plus(d);
        }

        @Override
        public Instant instant() {
            return now;
        }

        @Override
        public java.time.ZoneId getZone() {
            return ZoneOffset.UTC;
        }

        @Override
        public Clock withZone(java.time.ZoneId zone) {
            return this;
        }
    }
}
