package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.service.MailDelivery;

/**
 * Follows what became of each message of an alert (the Mail Manager's {@link MailDelivery}, a channel's
 * {@link ChannelDelivery}): a delivery or a failure is logged once, in words; a channel message of a named contact
 * that failed after it was handed over is followed by the contact's next channels at once ({@link LateFallback}).
 */
final class DeliveryWatch {

    private final ContactBook contacts;
    private final ChannelSender sender;
    private final LateFallback late;
    private final Consumer<String> events;
    private final Consumer<String> problems;

    DeliveryWatch(ContactBook contacts, ChannelSender sender, LateFallback late, Consumer<String> events,
            Consumer<String> problems) {
        this.contacts = contacts;
        this.sender = sender;
        this.late = late;
        this.events = events;
        this.problems = problems;
    }

    /**
     * @param at the platform time: a channel message of a named contact that failed later (an SMS gammu-smsd moved to
     *           {@code error/}, a push the server refused) is then followed by the contact's next channels at once;
     *           null = no fallback
     * @return {@code a} with the latest word on each message not finished yet
     */
    Alert refresh(Alert a, Instant at) {
        if (!waiting(a)) {
            return a;
        }
        List<Notification> now = new ArrayList<>();
        List<Notification> failedLater = new ArrayList<>();
        boolean changed = false;
        for (Notification n : a.notifications()) {
            Optional<ChannelDelivery> d = unfinished(n) ? sender.latest(n) : Optional.empty();
            if (d.isPresent() && (d.get().outcome() != n.outcome() || !d.get().detail().equals(n.detail()))) {
                now.add(n.with(d.get().outcome(), d.get().detail()));
                changed = true;
                String which = n.step().name().toLowerCase().replace('_', ' ') + " message" + (Notification.MAIL
                        .equals(n.channel()) && contacts.get(AlertText.who(n.to())).map(ContactBook.Contact::plain)
                        .orElse(true) ? "" : " to " + AlertText.who(n.to()) + " by " + ChannelSender.word(n.channel()));
                if (d.get().outcome() == MailDelivery.Outcome.SENT) {
                    events.accept("alert " + a.id() + ": its " + which + " was delivered (" + d.get().detail() + ")");
                }
                if (d.get().outcome() == MailDelivery.Outcome.FAILED) {
                    problems.accept("alert " + a.id() + ": its " + which + " was NOT delivered: " + d.get().detail());
                    failedLater.add(now.get(now.size() - 1));
                }
            } else {
                now.add(n);
            }
        }
        if (at != null && a.isOpen()) {
            failedLater.forEach(n -> now.addAll(late.after(a, n, now, at, told(a))));
        }
        return !changed ? a : Copies.notifications(a, now, a.contactsReached());
    }

    /** @return everyone told of {@code a} so far (empty = the Mail Manager's recipients) */
    static List<String> told(Alert a) {
        List<String> told = new ArrayList<>();
        a.notifications().forEach(n -> told.addAll(n.to()));
        return List.copyOf(new LinkedHashSet<>(told));
    }

    /** @return true while a message of {@code a} is not finished (its outcome is asked for at each tick) */
    static boolean waiting(Alert a) {
        return a.notifications().stream().anyMatch(DeliveryWatch::unfinished);
    }

    private static boolean unfinished(Notification n) {
        return n.outcome() == MailDelivery.Outcome.QUEUED || n.outcome() == MailDelivery.Outcome.RETRYING
                || n.outcome() == MailDelivery.Outcome.UNKNOWN;
    }
}
