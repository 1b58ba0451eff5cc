package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;
import java.util.function.Supplier;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Reaches one named contact along its addresses in order: mail through the Mail Manager, SMS and push
 * through their {@link MessageChannel}s. A channel that fails at once (modem not answering, server refusing, no
 * such channel running) is recorded as FAILED with its reason and the next one is tried; the first that takes the
 * message ends the attempt. Every attempt is one {@link Notification} with its channel.
 */
final class ChannelSender {

    /** What one attempt to reach a contact gave: a notification per channel tried, and the outcome in words. */
    record Reach(String contact, List<Notification> tried, boolean reached, String words) {
    }

    private final Supplier<MailManagerProvider> mail;
    private final Function<String, MessageChannel> channels;

    ChannelSender(Supplier<MailManagerProvider> mail, Function<String, MessageChannel> channels) {
        this.mail = mail;
        this.channels = channels;
    }

    Reach reach(ContactBook.Contact c, Instant now, NotificationStep step, String subject, String body,
            ChannelMessage phone) {
        List<Notification> tried = new ArrayList<>();
        List<String> failures = new ArrayList<>();
        for (ContactBook.Address ad : c.addresses()) {
            ChannelDelivery d = attempt(ad, subject, body, phone);
            tried.add(new Notification(now, step, List.of(c.key()), d.id(), d.outcome(), d.detail(), ad.scheme()));
            if (d.outcome() != MailDelivery.Outcome.FAILED) {
                String how = "by " + word(ad.scheme()) + " to " + ad.value() + " (" + d.detail() + ")";
                return new Reach(c.key(), tried, true, failures.isEmpty() ? how
                        : how + ", because " + String.join("; ", failures));
            }
            failures.add(word(ad.scheme()) + " to " + ad.value() + " failed: " + d.detail());
        }
        return new Reach(c.key(), tried, false, "NOT reached by any of their channels: " + String.join("; ",
                failures));
    }

    /** @return the channel's latest word on a message sent by {@code n}, if it knows it */
    Optional<ChannelDelivery> latest(Notification n) {
        if (n.mailId().isEmpty()) {
            return Optional.empty();
        }
        if (Notification.MAIL.equals(n.channel())) {
            MailManagerProvider m = mail.get();
            return m == null ? Optional.empty() : m.delivery(n.mailId())
                    .map(d -> new ChannelDelivery(d.id(), d.outcome(), d.detail()));
        }
        MessageChannel ch = channels.apply(n.channel());
        try {
            return ch == null ? Optional.empty() : ch.delivery(n.mailId());
        } catch (RuntimeException e) {
            return Optional.empty();
        }
    }

    private ChannelDelivery attempt(ContactBook.Address ad, String subject, String body, ChannelMessage phone) {
        if (Notification.MAIL.equals(ad.scheme())) {
            MailManagerProvider m = mail.get();
            if (m == null) {
                return ChannelDelivery.failed("no Mail Manager is running");
            }
            try {
                return new ChannelDelivery(m.sendTo(List.of(ad.value()), subject, body), MailDelivery.Outcome.QUEUED,
                        "handed to the Mail Manager");
            } catch (RuntimeException e) {
                return ChannelDelivery.failed("the Mail Manager refused it: " + e.getMessage());
            }
        }
        MessageChannel ch = channels.apply(ad.scheme());
        if (ch == null) {
            return ChannelDelivery.failed("no " + word(ad.scheme()) + " channel is running (bundle org.tinysep."
                    + ad.scheme() + ")");
        }
        try {
            return ch.send(ad.value(), phone);
        } catch (RuntimeException e) {
            return ChannelDelivery.failed(ch.name() + " failed: " + e.getMessage());
        }
    }

    /** @return the channel in words: e-mail, SMS, push */
    static String word(String scheme) {
        return switch (scheme) {
            case "mail" -> "e-mail";
            case "sms" -> "SMS";
            default -> scheme;
        };
    }
}
