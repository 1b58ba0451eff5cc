package org.tinysep.device.support.intake;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.intake.SourceGate.Verdict;

class SourceGateTest {

    private static InetAddress ip(String s) throws Exception {
        return InetAddress.getByName(s);
    }

    @Test
    void loopbackBindAcceptsEveryone() throws Exception {
        SourceGate g = SourceGate.of("127.0.0.1", "", 1);
        assertFalse(g.enforced());
        for (int i = 0; i < 10; i++) {
            assertEquals(Verdict.PASS, g.check(ip("127.0.0.2")));
        }
    }

    @Test
    void anyAddressBindAllowsOnlyTheListDefaultLocalhost() throws Exception {
        SourceGate g = SourceGate.of("0.0.0.0", "", 0);
        assertTrue(g.enforced());
        assertEquals(Verdict.PASS, g.check(ip("127.0.0.1")));
        assertEquals(Verdict.NOT_ALLOWED, g.check(ip("127.0.0.2")));
        assertEquals(Verdict.NOT_ALLOWED, g.check(ip("192.168.1.5")));
        assertEquals(2, g.notAllowed());
        SourceGate block = SourceGate.of("0.0.0.0", "10.1.0.0/16, 192.168.1.20", 0);
        assertEquals(Verdict.PASS, block.check(ip("10.1.200.3")));
        assertEquals(Verdict.NOT_ALLOWED, block.check(ip("10.2.0.1")));
        assertEquals(Verdict.PASS, block.check(ip("192.168.1.20")));
        assertEquals(Verdict.NOT_ALLOWED, block.check(ip("192.168.1.21")));
    }

    @Test
    void badEntriesAreNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SourceGate.of("0.0.0.0", "127.0.0.1, base-station.local", 0));
        assertTrue(e.getMessage().contains("'base-station.local'"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> SourceGate.of("0.0.0.0", "10.0.0.0/40", 0));
    }

    @Test
    void aFloodingSourceIsLimitedAndTheOthersAreNot() throws Exception {
        AtomicLong nanos = new AtomicLong();
        SourceGate g = SourceGate.of("0.0.0.0", "127.0.0.0/8", 100, nanos::get);
        int passed = 0;
        for (int i = 0; i < 10_000; i++) {
            if (g.check(ip("127.0.0.2")) == Verdict.PASS) {
                passed++;
            }
        }
        assertEquals(100, passed, "one second's worth in a burst");
        assertEquals(9_900, g.rateLimited());
        assertEquals(Verdict.PASS, g.check(ip("127.0.0.1")), "another source still gets through");
        nanos.addAndGet(500_000_000L);
        passed = 0;
        for (int i = 0; i < 1000; i++) {
            if (g.check(ip("127.0.0.2")) == Verdict.PASS) {
                passed++;
            }
        }
        assertEquals(50, passed, "refilled at 100/s");
    }
}
