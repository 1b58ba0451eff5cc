package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.MutableClock;

class LoginLimiterTest {

    private final MutableClock clock = new MutableClock(Instant.parse("2026-11-25T12:00:00Z"));

    @Test
    void aClientIsStoppedAfterTooManyFailuresUntilTheWindowHasPassed() {
        LoginLimiter limiter = new LoginLimiter(3, Duration.ofSeconds(60), clock);
        for (int i = 0; i < 3; i++) {
            assertFalse(limiter.waitFor("10.0.0.1", "installer").refused());
            limiter.failed("10.0.0.1", "installer");
            clock.advance(Duration.ofSeconds(1));
        }
        LoginLimiter.Wait wait = limiter.waitFor("10.0.0.1", "caregiver");
        assertEquals(Duration.ofSeconds(57), wait.duration(), "every account, from that address");
        assertTrue(wait.reason().contains("your address"), wait.reason());
        assertFalse(limiter.waitFor("10.0.0.2", "installer").refused(), "another client may still try");
        clock.advance(Duration.ofSeconds(57));
        assertFalse(limiter.waitFor("10.0.0.1", "installer").refused());
    }

    /** Issue 25, item 4: 20 failures from 127.0.0.2–.5 used to refuse the right caregiver from every address. */
    @Test
    void aFloodFromOtherAddressesDoesNotLockTheRightUserOut() {
        LoginLimiter limiter = new LoginLimiter(5, Duration.ofSeconds(60), clock);
        for (int minute = 0; minute < 3; minute++) { // repeated each minute, as the attacker did
            for (int host = 2; host <= 5; host++) {
                for (int i = 0; i < 5; i++) {
                    limiter.failed("127.0.0." + host, "caregiver");
                }
            }
            assertFalse(limiter.waitFor("127.0.0.1", "caregiver").refused(), "the right caregiver at 127.0.0.1");
            assertFalse(limiter.waitFor("127.0.0.1", "installer").refused());
            assertTrue(limiter.waitFor("127.0.0.3", "caregiver").refused(), "the flooding addresses are stopped");
            clock.advance(Duration.ofSeconds(61));
        }
    }

    @Test
    void manyAddressesGuessingOneAccountGetOneGuessEachPerWindow() {
        LoginLimiter limiter = new LoginLimiter(2, Duration.ofSeconds(60), clock);
        for (int i = 0; i < 8; i++) { // 4 × 2 failures as the installer, one from each of eight addresses
            limiter.failed("10.0.0." + i, "installer");
        }
        LoginLimiter.Wait wait = limiter.waitFor("10.0.0.3", "installer");
        assertTrue(wait.refused(), "an address that failed on the attacked account waits");
        assertTrue(wait.reason().contains("several addresses"), wait.reason());
        assertFalse(limiter.waitFor("10.0.0.3", "caregiver").refused(), "only for that account");
        assertFalse(limiter.waitFor("10.0.0.99", "installer").refused(), "an address without failures may log in");
        clock.advance(Duration.ofSeconds(61));
        assertFalse(limiter.waitFor("10.0.0.3", "installer").refused());
    }

    @Test
    void aFloodIsReportedOnceWithItsNumbers() {
        LoginLimiter limiter = new LoginLimiter(5, Duration.ofSeconds(60), clock);
        List<String> reports = new ArrayList<>();
        for (int minute = 0; minute < 5; minute++) {
            for (int i = 0; i < 20; i++) {
                limiter.failed("127.0.0." + (2 + i % 4), "caregiver").ifPresent(reports::add);
            }
            clock.advance(Duration.ofSeconds(61));
        }
        assertEquals(1, reports.size(), reports.toString());
        assertTrue(reports.get(0).startsWith("20 or more failed web console logins within 60 s, from 4 address(es),"
                + " the latest from 127.0.0.5 as 'caregiver' (20 failed logins since"), reports.get(0));
        assertEquals(100, limiter.total());
        clock.advance(Duration.ofSeconds(60 * LoginLimiter.QUIET_WINDOWS));
        for (int i = 0; i < 20; i++) {
            limiter.failed("127.0.0.9", "installer").ifPresent(reports::add);
        }
        assertEquals(2, reports.size(), "a new flood after a quiet time is reported again");
    }

    @Test
    void successForgetsTheFailuresOnThatAccountButNotTheAddresssCount() {
        LoginLimiter limiter = new LoginLimiter(2, Duration.ofSeconds(60), clock);
        for (int i = 0; i < 8; i++) {
            limiter.failed("10.0.0." + i, "caregiver");
        }
        limiter.succeeded("10.0.0.1", "caregiver");
        assertFalse(limiter.waitFor("10.0.0.1", "caregiver").refused());
        limiter.failed("a", "caregiver");
        limiter.succeeded("a", "caregiver");
        limiter.failed("a", "installer");
        assertTrue(limiter.waitFor("a", "installer").refused(), "knowing one password earns no more guesses");
    }

    @Test
    void anIpv6ClientCountsByItsNetwork() {
        assertEquals("2001:db8:1:2::/64", LoginLimiter.address("2001:db8:1:2:aaaa::1"));
        assertEquals(LoginLimiter.address("2001:db8:1:2::5"), LoginLimiter.address("2001:db8:1:2:ffff::9"));
        assertEquals("127.0.0.1", LoginLimiter.address("127.0.0.1"));
        assertEquals("0:0:0:0:0:0:0:1", LoginLimiter.address("0:0:0:0:0:0:0:1"));
    }
}
