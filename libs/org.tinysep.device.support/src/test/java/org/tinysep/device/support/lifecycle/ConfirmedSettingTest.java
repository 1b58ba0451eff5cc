package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class ConfirmedSettingTest {

    private final List<String> events = new ArrayList<>();
    private final List<Integer> sent = new ArrayList<>();
    private static final Instant T0 = Instant.parse("2026-11-25T17:30:00Z");
    /** The platform clock of the requests; reports carry their own time. */
    private Instant now = T0;
    private final ConfirmedSetting<Integer> level = new ConfirmedSetting<>(v -> "level " + v, Duration.ofSeconds(20),
            () -> now, events::add);

    /** A report {@code seconds} after T0. */
    private Optional<Integer> report(int value, int seconds) {
        return level.report(value, T0.plusSeconds(seconds));
    }

    @Test
    void reportsChangesOnlyAndStartsUnknown() {
        assertEquals(Optional.empty(), level.value());
        assertEquals(Optional.of(10), report(10, 0));
        assertEquals(Optional.empty(), report(10, 0));
        assertEquals(Optional.of(20), report(20, 0));
        assertEquals(Optional.of(20), level.value());
        assertEquals(List.of("level 10", "level 20"), events);
    }

    @Test
    void aRequestIsPendingUntilAReportEqualsIt() {
        report(10, 0);
        assertTrue(level.request(40, () -> sent.add(40)));
        assertEquals(List.of(40), sent);
        assertEquals(Optional.of(40), level.pending());
        assertEquals("40", level.pendingParameter().value());
        assertEquals(Optional.of(10), level.value(), "not changed by the request itself");

        assertEquals(Optional.of(40), report(40, 0));
        assertEquals(Optional.empty(), level.pending());
        assertEquals("", level.pendingParameter().value());
        assertEquals(List.of("level 10", "level 40 requested", "level 40 (confirmed)"), events);
    }

    @Test
    void confirmingTheCurrentValueIsLoggedButIsNoChange() {
        report(10, 0);
        level.request(10, () -> sent.add(10));
        assertEquals(Optional.empty(), report(10, 0));
        assertEquals(Optional.empty(), level.pending());
        assertEquals("level 10 (confirmed)", events.get(events.size() - 1));
    }

    @Test
    void disagreeingReportsWithinThePatienceMayPredateTheCommandAndAreNoContradiction() {
        // issue 17: a lagging bus radio delivered two or three of the node's periodic reports, sent before the
        // command reached it, after the request; the old rule (two disagreeing reports) gave a light up that did
        // switch. Within the patience any number of them is no contradiction.
        report(10, 0);
        level.request(40, () -> sent.add(40));
        report(10, 0);
        report(10, 5);
        report(10, 10);
        report(10, 19);
        assertEquals(Optional.of(40), level.pending(), events.toString());
        assertEquals(Optional.of(40), report(40, 19));
        assertEquals(Optional.empty(), level.pending());
        assertFalse(events.stream().anyMatch(e -> e.contains("given up")), events.toString());
        assertEquals("level 40 (confirmed)", events.get(events.size() - 1));
    }

    @Test
    void aReportThatStillDisagreesAtThePatienceGivesTheRequestUpAndSaysWhichReport() {
        report(10, 0);
        now = T0.plusSeconds(3);
        level.request(40, () -> sent.add(40));
        report(10, 22);
        assertEquals(Optional.of(40), level.pending(), "22 s is 19 s after the request: may still predate it");
        report(10, 23);
        assertEquals(Optional.empty(), level.pending());
        assertEquals("level 40 not confirmed: the node reported level 10 at 2026-11-25T17:30:23Z, 20 s after the "
                + "request (2026-11-25T17:30:03Z); request given up", events.get(events.size() - 1));
        assertEquals(Optional.of(10), level.value());
    }

    @Test
    void aNewerRequestReplacesTheOlderAndRestartsThePatience() {
        report(10, 0);
        level.request(40, () -> { });
        now = T0.plusSeconds(15);
        level.request(50, () -> { });
        report(10, 25);
        assertEquals(Optional.of(50), level.pending(), "10 s after the request for 50, not 25");
        assertEquals(Optional.of(50), report(50, 26));
        assertEquals(Optional.empty(), level.pending());
        assertFalse(events.stream().anyMatch(e -> e.contains("not confirmed")), events.toString());
    }

    @Test
    void aFailedSendIsLoggedNotThrownAndLeavesNothingPending() {
        boolean ok = level.request(40, () -> {
            throw new IllegalStateException("bus radio is closed");
        });
        assertFalse(ok);
        assertEquals(Optional.empty(), level.pending());
        assertEquals(List.of("level 40 requested", "level 40 not sent: bus radio is closed"), events);
    }

    @Test
    void theCommandIsSentBeforeItsRequestIsWritten() {
        List<Integer> linesAtSend = new ArrayList<>();
        assertTrue(level.request(40, () -> linesAtSend.add(events.size())));
        assertEquals(List.of(0), linesAtSend, "event-log lines written before the command was sent");
        assertEquals(List.of("level 40 requested"), events);
    }

    @Test
    void rejectsNonsense() {
        assertThrows(IllegalArgumentException.class,
                () -> new ConfirmedSetting<Integer>(v -> "", Duration.ZERO, () -> now, e -> { }));
        assertThrows(NullPointerException.class, () -> level.request(null, () -> { }));
        assertThrows(NullPointerException.class, () -> level.report(null, T0));
        assertThrows(NullPointerException.class, () -> level.report(1, null));
    }
}
