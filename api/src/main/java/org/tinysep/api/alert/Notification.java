package org.tinysep.api.alert;

import java.time.Instant;
import java.util.List;
import java.util.Objects;
import org.tinysep.api.service.MailDelivery;

/**
 * One message sent about an alert.
 *
 * @param at       when it was handed to the Mail Manager (platform time)
 * @param step     why it was sent
 * @param to       the addresses it went to (empty: the Mail Manager's configured recipients)
 * @param mailId   the Mail Manager's id of the message (empty when it could not be handed over)
 * @param outcome  what became of it, as far as known ({@link MailDelivery.Outcome})
 * @param detail   the outcome in plain words, e.g. "delivered to carer@example.org" or "no Mail Manager"
 */
public record Notification(Instant at, NotificationStep step, List<String> to, String mailId,
        MailDelivery.Outcome outcome, String detail) {

    public Notification {
        Objects.requireNonNull(at, "at");
        Objects.requireNonNull(step, "step");
        to = to == null ? List.of() : List.copyOf(to);
        mailId = mailId == null ? "" : mailId;
        Objects.requireNonNull(outcome, "outcome");
        detail = detail == null ? "" : detail;
    }

    /** @return this notification with a newer outcome */
    public Notification with(MailDelivery.Outcome next, String why) {
        return new Notification(at, step, to, mailId, next, why);
    }
}
