package org.tinysep.device.support.time;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class BackoffTest {

    private static List<Long> delays(Backoff b, int n) {
        List<Long> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            b = b.failed();
            out.add(b.delaySeconds());
        }
        return out;
    }

    @Test
    void doublesFromTheFirstWaitUpToTheLongest() {
        assertEquals(List.of(5L, 10L, 20L, 40L, 80L, 160L, 320L, 600L, 600L, 600L),
                delays(Backoff.ofSeconds(5, 600), 10), "the Mail Manager's defaults");
        assertEquals(List.of(1L, 2L, 4L, 8L, 16L, 30L, 30L), delays(Backoff.ofSeconds(1, 30), 7), "MQTT");
        assertEquals(List.of(1L, 2L, 4L, 8L, 16L, 32L, 60L, 60L), delays(Backoff.ofSeconds(1, 60), 8), "supervisor");
    }

    @Test
    void aSuccessStartsAgainAndTheValueNeverChanges() {
        Backoff start = Backoff.ofSeconds(5, 600);
        Backoff three = start.failed().failed().failed();
        assertEquals(20, three.delaySeconds());
        assertEquals(3, three.failures());
        assertEquals(0, start.failures(), "immutable");
        assertEquals(Duration.ZERO, start.delay(), "no wait before any failure");
        assertEquals(start, three.reset());
        assertEquals(5, three.reset().failed().delaySeconds());
        assertSame(start, start.reset());
    }

    @Test
    void manyFailuresNeitherOverflowNorLoop() {
        Backoff b = new Backoff(Duration.ofSeconds(1), Duration.ofDays(1), Integer.MAX_VALUE);
        assertEquals(Duration.ofDays(1), b.delay());
        assertEquals(Integer.MAX_VALUE, b.failed().failures());
    }

    @Test
    void aMaximumBelowTheFirstWaitIsRaisedButBadValuesAreRefusedPlainly() {
        assertEquals(List.of(60L, 60L), delays(Backoff.ofSeconds(60, 10), 2));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Backoff.ofSeconds(0, 10));
        assertTrue(e.getMessage().contains("first wait must be positive"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> new Backoff(Duration.ofSeconds(10), Duration.ofSeconds(5), 0));
        assertTrue(e.getMessage().contains("below the first"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Backoff(Duration.ofSeconds(1), Duration.ofSeconds(5), -1));
    }
}
