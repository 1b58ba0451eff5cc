package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Sends the messages of alerts and says in the event log what was sent to whom: the schedule's step
 * ({@link Escalation}) becomes a message handed out by {@link MessageDispatch}; what became of each is followed by
 * {@link DeliveryWatch}. Without a Mail Manager nothing is recorded as sent, so the message due is sent as soon as
 * one appears.
 */
final class Notifier {

    private final AlertSettings settings;
    private final AlertText words;
    private final Consumer<String> events;
    private final Consumer<String> problems;
    private final MessageDispatch dispatch;
    private final DeliveryWatch watch;
    private boolean saidNoMail;
    /** What a queued message's entry adds: it is not delivered yet, and where the outcome will be told. */
    static final String QUEUED_NOTE = " (not delivered yet: its delivery or failure is logged when the Mail Manager "
            + "reports it)";

    Notifier(AlertSettings settings, AlertText words, Supplier<MailManagerProvider> mail, Consumer<String> events,
            Consumer<String> problems) {
        this(settings, ContactBook.EMPTY, s -> null, words, mail, events, problems);
    }

    /** @param channels the running {@link MessageChannel} of a scheme, or null */
    Notifier(AlertSettings settings, ContactBook contacts, Function<String, MessageChannel> channels, AlertText words,
            Supplier<MailManagerProvider> mail, Consumer<String> events, Consumer<String> problems) {
        ChannelSender sender = new ChannelSender(mail, channels);
        this.dispatch = new MessageDispatch(contacts, sender, mail);
        this.watch = new DeliveryWatch(contacts, sender, new LateFallback(contacts, sender, words, events, problems),
                events, problems);
        this.settings = settings;
        this.words = words;
        this.events = events;
        this.problems = problems;
    }

    AlertSettings settings() {
        return settings;
    }

    AlertText words() {
        return words;
    }

    Consumer<String> events() {
        return events;
    }

    /** @return {@code a} with the message of {@code step} sent, or {@code a} itself when there is no Mail Manager */
    Alert send(Alert a, Escalation.Step step, Instant now) {
        String subject = LateFallback.subject(words, a, step.step(), now);
        List<String> told = step.step() == NotificationStep.ESCALATION ? union(toldSoFar(a), step.to()) : toldSoFar(a);
        MessageDispatch.Sent d = dispatch.send(now, step.step(), step.to(), subject, words.body(a, told, now),
                new ChannelMessage(a.id(), subject, "Not acknowledged yet. Reply OK " + a.id() + " if you take care "
                        + "of it."));
        if (d.sent().isEmpty()) {
            if (!saidNoMail) {
                saidNoMail = true;
                problems.accept("alert " + a.id() + ": no Mail Manager to send its " + step.step().name()
                        .toLowerCase().replace('_', ' ') + " message; it is sent as soon as one is there");
            }
            return a;
        }
        saidNoMail = false;
        String prefix = switch (step.step()) {
            case FIRST -> "alert " + a.id() + ": first message";
            case REPEAT -> "alert " + a.id() + " not acknowledged: repeat";
            case ESCALATION -> "alert " + a.id() + " not acknowledged: passed on to the next contact, "
                    + AlertText.who(step.to()) + " (contact " + step.reached() + " of " + settings.contacts().size()
                    + ")";
            case ALL_CLEAR -> "alert " + a.id() + ": all clear";
        };
        if (d.mailed() != null) {
            // the Mail Manager only queued it: say so; what became of it is logged when the Mail Manager knows
            events.accept(switch (step.step()) {
                case FIRST -> prefix + " queued to the Mail Manager for " + AlertText.who(d.mailed());
                case REPEAT -> prefix + " queued to the Mail Manager for " + AlertText.who(d.mailed());
                case ESCALATION -> prefix + ", message queued to the Mail Manager";
                case ALL_CLEAR -> prefix + " queued to the Mail Manager for " + AlertText.who(d.mailed());
            } + QUEUED_NOTE);
        }
        tell(prefix, d);
        return Copies.notifications(a, concat(a.notifications(), d.sent()), step.reached());
    }

    private void tell(String prefix, MessageDispatch.Sent d) {
        for (ChannelSender.Reach r : d.reaches()) {
            (r.reached() ? events : problems).accept(prefix + " to " + r.contact() + " " + r.words());
        }
    }

    /** @return {@code cleared} with an all-clear message to everyone told of it (when a Mail Manager is there) */
    Alert allClear(Alert cleared, String why, Instant now) {
        if (cleared.notifications().isEmpty()) {
            return cleared; // nobody was told: nobody needs the all clear
        }
        List<String> to = toldSoFar(cleared);
        MessageDispatch.Sent d = dispatch.send(now, NotificationStep.ALL_CLEAR, to, words.allClearSubject(cleared),
                words.allClearBody(cleared, why), new ChannelMessage(cleared.id(), words.allClearSubject(cleared),
                        why + ". Nobody needs to come any more."));
        if (d.sent().isEmpty()) {
            problems.accept("alert " + cleared.id() + ": no Mail Manager to send the all clear (" + why + ")");
            return cleared;
        }
        tell("alert " + cleared.id() + ": all clear", d);
        return Copies.notifications(cleared, concat(cleared.notifications(), d.sent()), cleared.contactsReached());
    }

    /** @return everyone told of {@code a} so far (empty = the Mail Manager's recipients) */
    List<String> toldSoFar(Alert a) {
        return DeliveryWatch.told(a);
    }

    /** @return {@code a} with the Mail Manager's latest word on each message not finished yet */
    Alert refresh(Alert a) {
        return refresh(a, null);
    }

    /** @param at the platform time, for the fallback of a message that failed later ({@link DeliveryWatch}) */
    Alert refresh(Alert a, Instant at) {
        return watch.refresh(a, at);
    }

    /** Sends a message that belongs to no alert (the daily summary) to the Mail Manager's recipients. */
    Optional<String> sendPlain(String subject, String body) {
        return dispatch.sendPlain(subject, body);
    }

    private static List<Notification> concat(List<Notification> a, List<Notification> b) {
        List<Notification> all = new ArrayList<>(a);
        all.addAll(b);
        return all;
    }

    private static List<String> union(List<String> a, List<String> b) {
        Set<String> all = new LinkedHashSet<>(a);
        all.addAll(b);
        return List.copyOf(all);
    }
}
