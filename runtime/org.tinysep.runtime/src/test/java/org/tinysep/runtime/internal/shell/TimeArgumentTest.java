package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.time.ZoneId;
import org.junit.jupiter.api.Test;

class TimeArgumentTest {

    static final Instant NOW = Instant.parse("2026-11-22T12:00:00Z");
    static final ZoneId BERLIN = ZoneId.of("Europe/Berlin");

    private static Instant parse(String s) {
        return TimeArgument.parse(s, NOW, BERLIN);
    }

    @Test
    void acceptsInstantsLocalTimesDatesAndRelativeTimes() {
        assertEquals(Instant.parse("2026-11-22T10:00:00Z"), parse("2026-11-22T10:00:00Z"));
        assertEquals(Instant.parse("2026-11-22T10:00:00Z"), parse("2026-11-22T11:00+01:00"));
        assertEquals(Instant.parse("2026-11-22T10:00:00Z"), parse("2026-11-22T11:00"), "local time in Berlin");
        assertEquals(Instant.parse("2026-11-22T10:00:30Z"), parse("2026-11-22 11:00:30"));
        assertEquals(Instant.parse("2026-11-21T23:00:00Z"), parse("2026-11-22"));
        assertEquals(NOW, parse("now"));
        assertEquals(Instant.parse("2026-11-22T10:00:00Z"), parse("-2h"));
        assertEquals(Instant.parse("2026-11-20T22:30:00Z"), parse("-1d13h30m"));
        assertEquals(Instant.parse("2026-11-15T12:00:00Z"), parse("-1w"));
        assertEquals(Instant.parse("2026-11-22T11:59:15Z"), parse("-45s"));
    }

    @Test
    void rejectsAnythingElse() {
        for (String bad : new String[] {"", "yesterday", "-2", "-2x", "2h", "2026-11-22T25:00", "11:00"}) {
            assertThrows(IllegalArgumentException.class, () -> parse(bad), bad);
        }
    }
}
