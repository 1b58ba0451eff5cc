package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;

/**
 * Issue 25, item 8: the alert log says what really happened to a message: queued to the Mail Manager when handed
 * over, delivered (or not) when the Mail Manager says so; never "sent" when it was only queued.
 */
class NotifierTest {

    private static final Instant T = Instant.parse("2026-11-26T10:00:00Z");
    private static final AlertSettings S = new AlertSettings(List.of("a@x", "b@x"), 10, 15, LocalTime.of(8, 0),
            ZoneOffset.UTC);

    /** A Mail Manager that queues and is told later what became of each message. */
    private static final class Mail implements MailManagerProvider {
        final Map<String, MailDelivery> deliveries = new ConcurrentHashMap<>();

        @Override
        public String sendTo(List<String> to, String subject, String body) {
            String id = "m" + (deliveries.size() + 1);
            deliveries.put(id, new MailDelivery(id, subject, to, T, MailDelivery.Outcome.QUEUED, "handed to the Mail Manager", T));
            return id;
        }

        void delivered(String id) {
            MailDelivery d = deliveries.get(id);
            deliveries.put(id, new MailDelivery(id, d.subject(), d.to(), T, MailDelivery.Outcome.SENT,
                    "delivered to " + String.join(", ", d.to()), T.plusSeconds(5)));
        }

        @Override
        public Optional<MailDelivery> delivery(String id) {
            return Optional.ofNullable(deliveries.get(id));
        }

        @Override
        public void send(String subject, String body) {
            throw new UnsupportedOperationException();
        }

        @Override
        public MailStatus status() {
            return MailStatus.IDLE;
        }

        @Override
        public String deviceUid() {
            return "mail";
        }

        @Override
        public Connection connect(MailManagerListener listener) {
            throw new UnsupportedOperationException();
        }
    }

    private final Mail mail = new Mail();
    private final List<String> events = new ArrayList<>();
    private final Notifier notifier = new Notifier(S, new AlertText(ZoneOffset.UTC), () -> mail, events::add,
            events::add);

    @Test
    void theFirstMessageIsLoggedAsQueuedAndItsDeliveryWhenTheMailManagerKnows() {
        Alert a = Copies.raised("3", new AlertRequest(AlertKind.INACTIVITY, "inactivity", "r1", "Bathroom", T,
                "TinySEP: no activity in Bathroom since 09:15", "text"));
        a = notifier.send(a, new Escalation.Step(NotificationStep.FIRST, List.of("a@x"), 1), T);
        assertEquals(List.of("alert 3: first message queued to the Mail Manager for a@x (not delivered yet: its "
                + "delivery or failure is logged when the Mail Manager reports it)"), events);
        assertEquals(MailDelivery.Outcome.QUEUED, a.notifications().get(0).outcome());

        assertEquals(a, notifier.refresh(a), "still queued: nothing to log");
        assertEquals(1, events.size());
        mail.delivered("m1");
        a = notifier.refresh(a);
        assertEquals(MailDelivery.Outcome.SENT, a.notifications().get(0).outcome());
        assertEquals("alert 3: its first message was delivered (delivered to a@x)", events.get(1));
    }
}
