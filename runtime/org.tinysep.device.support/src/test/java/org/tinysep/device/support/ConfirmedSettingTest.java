package org.tinysep.device.support;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class ConfirmedSettingTest {

    private final List<String> events = new ArrayList<>();
    private final List<Integer> sent = new ArrayList<>();
    private final ConfirmedSetting<Integer> level = new ConfirmedSetting<>(v -> "level " + v, 2, events::add);

    @Test
    void reportsChangesOnlyAndStartsUnknown() {
        assertEquals(Optional.empty(), level.value());
        assertEquals(Optional.of(10), level.report(10));
        assertEquals(Optional.empty(), level.report(10));
        assertEquals(Optional.of(20), level.report(20));
        assertEquals(Optional.of(20), level.value());
        assertEquals(List.of("level 10", "level 20"), events);
    }

    @Test
    void aRequestIsPendingUntilAReportEqualsIt() {
        level.report(10);
        assertTrue(level.request(40, () -> sent.add(40)));
        assertEquals(List.of(40), sent);
        assertEquals(Optional.of(40), level.pending());
        assertEquals("40", level.pendingParameter().value());
        assertEquals(Optional.of(10), level.value(), "not changed by the request itself");

        assertEquals(Optional.of(40), level.report(40));
        assertEquals(Optional.empty(), level.pending());
        assertEquals("", level.pendingParameter().value());
        assertEquals(List.of("level 10", "level 40 requested", "level 40 (confirmed)"), events);
    }

    @Test
    void confirmingTheCurrentValueIsLoggedButIsNoChange() {
        level.report(10);
        level.request(10, () -> sent.add(10));
        assertEquals(Optional.empty(), level.report(10));
        assertEquals(Optional.empty(), level.pending());
        assertEquals("level 10 (confirmed)", events.get(events.size() - 1));
    }

    @Test
    void aRequestIsGivenUpAfterPatienceDisagreeingReports() {
        level.report(10);
        level.request(40, () -> sent.add(40));
        level.report(10);
        assertEquals(Optional.of(40), level.pending(), "the first report may have been on its way already");
        level.report(10);
        assertEquals(Optional.empty(), level.pending());
        assertEquals("level 40 not confirmed: the node still reports level 10 after 2 status report(s); request "
                + "given up", events.get(events.size() - 1));
    }

    @Test
    void aNewerRequestReplacesTheOlderAndRestartsThePatience() {
        level.report(10);
        level.request(40, () -> { });
        level.report(10);
        level.request(50, () -> { });
        level.report(10);
        assertEquals(Optional.of(50), level.pending(), "one disagreement with 50 so far, not two");
        assertEquals(Optional.of(50), level.report(50));
        assertEquals(Optional.empty(), level.pending());
        assertFalse(events.stream().anyMatch(e -> e.startsWith("level 40 not confirmed")), events.toString());
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
    void rejectsNonsense() {
        assertThrows(IllegalArgumentException.class, () -> new ConfirmedSetting<Integer>(v -> "", 0, e -> { }));
        assertThrows(NullPointerException.class, () -> level.request(null, () -> { }));
        assertThrows(NullPointerException.class, () -> level.report(null));
    }
}
