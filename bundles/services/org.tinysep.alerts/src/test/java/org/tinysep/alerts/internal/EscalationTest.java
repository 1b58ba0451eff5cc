package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.service.MailDelivery;

/** The schedule of an open alert from its history, and the alerts file surviving a round trip. */
class EscalationTest {

    private static final Instant T = Instant.parse("2026-11-26T10:00:00Z");
    private static final AlertSettings S = new AlertSettings(List.of("a@x", "b@x", "c@x"), 10, 15,
            LocalTime.of(8, 0), ZoneOffset.UTC);

    @TempDir
    Path dir;

    /** Runs the schedule minute by minute for an hour: what is sent when, and to whom. */
    @Test
    void repeatsAndEscalatesOnSchedule() {
        Alert a = alert(AlertState.OPEN, List.of());
        List<String> sent = new ArrayList<>();
        for (int m = 0; m <= 40; m++) {
            Instant now = T.plusSeconds(m * 60L);
            var step = Escalation.due(a, S, now);
            if (step.isPresent()) {
                sent.add(m + " " + step.get().step() + " " + step.get().to());
                List<Notification> all = new ArrayList<>(a.notifications());
                all.add(new Notification(now, step.get().step(), step.get().to(), "1", MailDelivery.Outcome.QUEUED,
                        ""));
                a = new Alert(a.id(), a.kind(), a.source(), "", "", a.raisedAt(), a.subject(), a.text(), a.state(),
                        step.get().reached(), null, "", all);
            }
        }
        assertEquals(List.of("0 FIRST [a@x]", "10 REPEAT [a@x]", "15 ESCALATION [b@x]", "25 REPEAT [a@x, b@x]",
                "30 ESCALATION [c@x]", "40 REPEAT [a@x, b@x, c@x]"), sent);
    }

    @Test
    void nothingForAnAcknowledgedAlertAndOnlyRepeatsWithoutContacts() {
        Notification first = new Notification(T, NotificationStep.FIRST, List.of("a@x"), "1",
                MailDelivery.Outcome.SENT, "");
        assertTrue(Escalation.due(alert(AlertState.ACKNOWLEDGED, List.of(first)), S, T.plusSeconds(7200)).isEmpty());
        AlertSettings none = new AlertSettings(List.of(), 10, 15, null, ZoneOffset.UTC);
        var step = Escalation.due(alert(AlertState.OPEN, List.of(first)), none, T.plusSeconds(3600)).orElseThrow();
        assertEquals(NotificationStep.REPEAT, step.step());
        assertEquals(List.of(), step.to()); // the Mail Manager's recipients
    }

    @Test
    void theAlertsFileKeepsEverything() throws Exception {
        AlertStore store = new AlertStore(dir.resolve("alerts/alerts.properties"));
        Alert a = alert(AlertState.OPEN, List.of(new Notification(T, NotificationStep.FIRST, List.of("a@x", "b@x"),
                "17", MailDelivery.Outcome.RETRYING, "to a@x: delivery failed temporarily (452 …), retrying")));
        store.save(new AlertStore.Content(List.of(a), 7, LocalDate.of(2026, 11, 26)));
        AlertStore.Content c = store.load(p -> { throw new AssertionError(p); });
        assertEquals(List.of(a), c.alerts());
        assertEquals(7, c.lastId());
        assertEquals(LocalDate.of(2026, 11, 26), c.lastSummary());
    }

    private static Alert alert(AlertState state, List<Notification> ns) {
        return new Alert("3", AlertKind.INACTIVITY, "inactivity", "", "", T, "TinySEP: no activity in Bathroom",
                "text\nwith lines = and : signs", state, ns.isEmpty() ? 0 : 1, null, "", ns);
    }
}
