package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.service.MailDelivery;

/** The caregiver page says which channel reached whom, in words (issue 27). */
class AlertReachTest {

    private static final Instant T = Instant.parse("2026-11-29T03:00:00Z");

    @Test
    void eachMessageSaysItsChannelWhoAndWhatBecameOfIt() {
        Alert a = new Alert("3", AlertKind.INACTIVITY, "inactivity", "r", "Bathroom", T, "s", "t", AlertState.OPEN, 2,
                null, "", List.of(
                        new Notification(T, NotificationStep.FIRST, List.of("Eva"), "", MailDelivery.Outcome.FAILED,
                                "gammu-smsd is not running", "sms"),
                        new Notification(T, NotificationStep.FIRST, List.of("Eva"), "m1", MailDelivery.Outcome.SENT,
                                "delivered to eva@example.org", Notification.MAIL),
                        new Notification(T, NotificationStep.ESCALATION, List.of("Otto"), "p1",
                                MailDelivery.Outcome.SENT, "", "push"),
                        new Notification(T, NotificationStep.REPEAT, List.of(), "m2", MailDelivery.Outcome.QUEUED,
                                "")));
        assertEquals(List.of("first message to Eva by SMS: NOT delivered (gammu-smsd is not running)",
                "first message to Eva by e-mail: delivered (delivered to eva@example.org)",
                "escalation to Otto by push: delivered",
                "repeat to the Mail Manager's recipients by e-mail: on its way"), AlertReach.lines(a));
    }
}
