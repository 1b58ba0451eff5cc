package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Hands one message to everyone it is for: the plain addresses get one mail through the Mail Manager, each named
 * contact is reached along its own channels ({@link ChannelSender}).
 */
final class MessageDispatch {

    /** What one message gave: every notification, the plain addresses mailed (null: none), each named contact's. */
    record Sent(List<Notification> sent, List<String> mailed, List<ChannelSender.Reach> reaches) {
    }

    private final ContactBook contacts;
    private final ChannelSender sender;
    private final Supplier<MailManagerProvider> mail;

    MessageDispatch(ContactBook contacts, ChannelSender sender, Supplier<MailManagerProvider> mail) {
        this.contacts = contacts;
        this.sender = sender;
        this.mail = mail;
    }

    /** @param to contact keys and plain addresses; empty = the Mail Manager's recipients */
    Sent send(Instant now, NotificationStep step, List<String> to, String subject, String body,
            ChannelMessage phone) {
        List<String> plain = to.stream().filter(k -> contacts.get(k).map(ContactBook.Contact::plain).orElse(true))
                .toList();
        List<Notification> sent = new ArrayList<>();
        List<String> mailed = null;
        if (!plain.isEmpty() || to.isEmpty()) {
            Optional<Notification> n = hand(now, step, plain, subject, body);
            if (n.isPresent()) {
                sent.add(n.get());
                mailed = plain;
            }
        }
        List<ChannelSender.Reach> reaches = new ArrayList<>();
        for (String k : to) {
            contacts.get(k).filter(c -> !c.plain()).ifPresent(c -> {
                ChannelSender.Reach r = sender.reach(c, now, step, subject, body, phone);
                sent.addAll(r.tried());
                reaches.add(r);
            });
        }
        return new Sent(sent, mailed, reaches);
    }

    /** Sends a message that belongs to no alert (the daily summary) to the Mail Manager's recipients. */
    Optional<String> sendPlain(String subject, String body) {
        MailManagerProvider m = mail.get();
        if (m == null) {
            return Optional.empty();
        }
        return Optional.of(sendTo(m, List.of(), subject, body));
    }

    private Optional<Notification> hand(Instant now, NotificationStep step, List<String> to, String subject,
            String body) {
        MailManagerProvider m = mail.get();
        if (m == null) {
            return Optional.empty();
        }
        String id = sendTo(m, to, subject, body);
        return Optional.of(new Notification(now, step, to, id, MailDelivery.Outcome.QUEUED,
                "handed to the Mail Manager"));
    }

    private static String sendTo(MailManagerProvider m, List<String> to, String subject, String body) {
        try {
            return m.sendTo(to, subject, body);
        } catch (UnsupportedOperationException e) { // a Mail Manager before API 1.1: its recipients only
            m.send(subject, body);
            return "";
        }
    }
}
