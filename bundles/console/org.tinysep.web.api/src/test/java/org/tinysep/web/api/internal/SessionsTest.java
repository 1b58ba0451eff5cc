package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.MutableClock;
import org.tinysep.web.api.internal.Sessions.Session;

class SessionsTest {

    private final MutableClock clock = new MutableClock(Instant.parse("2026-11-25T12:00:00Z"));

    @Test
    void aSessionEndsAfterItsIdleTimeOrOnLogout() {
        Sessions sessions = new Sessions(Duration.ofMinutes(10), clock);
        Session s = sessions.open(Role.CAREGIVER);
        assertNotEquals(s.token(), s.csrf());
        assertTrue(s.token().length() >= 43, "256 random bits");
        clock.advance(Duration.ofMinutes(9));
        assertEquals(Role.CAREGIVER, sessions.find(s.token()).orElseThrow().role());
        clock.advance(Duration.ofMinutes(9)); // used 9 min ago: still alive
        assertTrue(sessions.find(s.token()).isPresent());
        clock.advance(Duration.ofMinutes(11));
        assertTrue(sessions.find(s.token()).isEmpty());
        Session t = sessions.open(Role.INSTALLER);
        sessions.close(t.token());
        assertTrue(sessions.find(t.token()).isEmpty());
        assertTrue(sessions.find(null).isEmpty());
        assertTrue(sessions.find("guessed").isEmpty());
    }

    /** Issue 25, item 5: what a live stream asks every second; asking does not keep the session alive. */
    @Test
    void aliveSaysWhetherTheSessionStillExistsWithoutUsingIt() {
        Sessions sessions = new Sessions(Duration.ofMinutes(10), clock);
        Session s = sessions.open(Role.CAREGIVER);
        assertTrue(sessions.alive(s.token()));
        clock.advance(Duration.ofMinutes(6));
        assertTrue(sessions.alive(s.token()));
        clock.advance(Duration.ofMinutes(6));
        assertFalse(sessions.alive(s.token()), "idle for 12 minutes: asking did not count as a use");
        Session t = sessions.open(Role.INSTALLER);
        sessions.close(t.token());
        assertFalse(sessions.alive(t.token()));
        Session u = sessions.open(Role.INSTALLER);
        sessions.clear();
        assertFalse(sessions.alive(u.token()));
        assertFalse(sessions.alive(null));
    }
}
