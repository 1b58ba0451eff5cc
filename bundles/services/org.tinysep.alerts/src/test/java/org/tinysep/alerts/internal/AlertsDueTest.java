package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.service.MailDelivery;

/** Issue 29, idle: when the alert service's ticker needs to call it (every second only while there is work). */
class AlertsDueTest {

    private static final Instant NOW = Instant.parse("2026-11-30T10:15:00Z");
    private static final AlertSettings AT_8 = new AlertSettings(List.of(), 10, 15, LocalTime.of(8, 0),
            ZoneOffset.UTC);
    private static final LocalDate TODAY = LocalDate.of(2026, 11, 30);

    private static Alert alert(AlertState state, MailDelivery.Outcome outcome) {
        List<Notification> sent = outcome == null ? List.of()
                : List.of(new Notification(NOW.minusSeconds(60), NotificationStep.FIRST, List.of(), "m1", outcome, ""));
        return new Alert("1", AlertKind.HELP, "help:1", "", "", NOW.minusSeconds(60), "s", "t", state, 1,
                state == AlertState.OPEN ? null : NOW, "", sent);
    }

    @Test
    void withNothingOpenOrUnfinishedTheNextCallIsTomorrowsSummary() {
        Instant next = AlertManager.nextDue(List.of(alert(AlertState.ACKNOWLEDGED, MailDelivery.Outcome.SENT)), AT_8,
                TODAY, NOW);
        assertEquals(Instant.parse("2026-12-01T08:00:00Z"), next);
    }

    @Test
    void todaysSummaryNotYetSentIsDueAtItsTime() {
        assertEquals(Instant.parse("2026-11-30T08:00:00Z"), AlertManager.nextDue(List.of(), AT_8, TODAY.minusDays(1),
                Instant.parse("2026-11-30T07:00:00Z")));
        assertEquals(NOW, AlertManager.nextDue(List.of(), AT_8, TODAY.minusDays(1), NOW), "late: due at once");
    }

    @Test
    void anOpenAlertOrAMessageNotFinishedNeedsEveryTick() {
        assertEquals(NOW, AlertManager.nextDue(List.of(alert(AlertState.OPEN, MailDelivery.Outcome.SENT)), AT_8,
                TODAY, NOW));
        assertEquals(NOW, AlertManager.nextDue(List.of(alert(AlertState.CLEARED, MailDelivery.Outcome.QUEUED)), AT_8,
                TODAY, NOW), "an all clear still queued: its outcome is asked for each tick");
    }

    @Test
    void withoutASummaryTimeNothingIsDue() {
        AlertSettings none = new AlertSettings(List.of(), 10, 15, null, ZoneOffset.UTC);
        assertEquals(null, AlertManager.nextDue(List.of(), none, null, NOW));
    }
}
