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
 * @param channel  which channel it went by: {@value #MAIL} or a {@link org.tinysep.api.channel.MessageChannel}'s
 *                 scheme ({@code sms}, {@code push}); with {@code to} it says which channel reached whom (since 1.2)
 */
public record Notification(Instant at, NotificationStep step, List<String> to, String mailId,
        MailDelivery.Outcome outcome, String detail, String channel) {

    /** The channel of e-mail through the Mail Manager. */
    public static final String MAIL = "mail";

    /** A notification by e-mail (before 1.2 every notification was one). */
    public Notification(Instant at, NotificationStep step, List<String> to, String mailId,
            MailDelivery.Outcome outcome, String detail) {
        this(at, step, to, mailId, outcome, detail, MAIL);
    }

    public Notification {
        Objects.requireNonNull(at, "at");
        Objects.requireNonNull(step, "step");
        to = to == null ? List.of() : List.copyOf(to);
        mailId = mailId == null ? "" : mailId;
        Objects.requireNonNull(outcome, "outcome");
        detail = detail == null ? "" : detail;
        channel = channel == null || channel.isBlank() ? MAIL : channel;
    }

    /** @return this notification with a newer outcome */
    public Notification with(MailDelivery.Outcome next, String why) {
        return new Notification(at, step, to, mailId, next, why, channel);
    }
}
