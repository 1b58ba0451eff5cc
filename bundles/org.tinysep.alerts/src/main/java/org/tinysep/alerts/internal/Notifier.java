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
import org.tinysep.api.channel.ChannelDelivery;
import org.tinysep.api.channel.ChannelMessage;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Sends the messages of alerts through the Mail Manager and follows what became of each ({@link MailDelivery}).
 * Without a Mail Manager nothing is recorded as sent, so the message due is sent as soon as one appears.
 */
final class Notifier {

    private final AlertSettings settings;
    private final Words words;
    private final Supplier<MailManagerProvider> mail;
    private final Consumer<String> events;
    private final Consumer<String> problems;
    private final ContactBook contacts;
    private final ChannelSender sender;
    private final LateFallback late;
    private boolean saidNoMail;
    /** What a queued message's entry adds: it is not delivered yet, and where the outcome will be told. */
    static final String QUEUED_NOTE = " (not delivered yet: its delivery or failure is logged when the Mail Manager "
            + "reports it)";

    Notifier(AlertSettings settings, Words words, Supplier<MailManagerProvider> mail, Consumer<String> events,
            Consumer<String> problems) {
        this(settings, ContactBook.EMPTY, s -> null, words, mail, events, problems);
    }

    /** @param channels the running {@link MessageChannel} of a scheme, or null */
    Notifier(AlertSettings settings, ContactBook contacts, Function<String, MessageChannel> channels, Words words,
            Supplier<MailManagerProvider> mail, Consumer<String> events, Consumer<String> problems) {
        this.contacts = contacts;
        this.sender = new ChannelSender(mail, channels);
        this.late = new LateFallback(contacts, sender, words, events, problems);
        this.settings = settings;
        this.words = words;
        this.mail = mail;
        this.events = events;
        this.problems = problems;
    }

    AlertSettings settings() {
        return settings;
    }

    Words words() {
        return words;
    }

    Consumer<String> events() {
        return events;
    }

    /** @return {@code a} with the message of {@code step} sent, or {@code a} itself when there is no Mail Manager */
    Alert send(Alert a, Escalation.Step step, Instant now) {
        String subject = LateFallback.subject(words, a, step.step(), now);
        List<String> told = step.step() == NotificationStep.ESCALATION ? union(toldSoFar(a), step.to()) : toldSoFar(a);
        Dispatch d = dispatch(now, step.step(), step.to(), subject, words.body(a, told, now), new ChannelMessage(a.id(),
                subject, "Not acknowledged yet. Reply OK " + a.id() + " if you take care of it."));
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
                    + Words.who(step.to()) + " (contact " + step.reached() + " of " + settings.contacts().size()
                    + ")";
            case ALL_CLEAR -> "alert " + a.id() + ": all clear";
        };
        if (d.mailed() != null) {
            // the Mail Manager only queued it: say so; what became of it is logged when the Mail Manager knows
            events.accept(switch (step.step()) {
                case FIRST -> prefix + " queued to the Mail Manager for " + Words.who(d.mailed());
                case REPEAT -> prefix + " queued to the Mail Manager for " + Words.who(d.mailed());
                case ESCALATION -> prefix + ", message queued to the Mail Manager";
                case ALL_CLEAR -> prefix + " queued to the Mail Manager for " + Words.who(d.mailed());
            } + QUEUED_NOTE);
        }
        tell(prefix, d);
        return Copies.notifications(a, concat(a.notifications(), d.sent()), step.reached());
    }

    /** What one message gave: every notification, the plain addresses mailed (null: none), each named contact's. */
    private record Dispatch(List<Notification> sent, List<String> mailed, List<ChannelSender.Reach> reaches) {
    }

    /** Plain addresses get one mail as before; each named contact is reached along its channels (issue 27). */
    private Dispatch dispatch(Instant now, NotificationStep step, List<String> to, String subject, String body,
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
        return new Dispatch(sent, mailed, reaches);
    }

    private void tell(String prefix, Dispatch d) {
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
        Dispatch d = dispatch(now, NotificationStep.ALL_CLEAR, to, words.allClearSubject(cleared),
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
        List<String> told = new ArrayList<>();
        a.notifications().forEach(n -> told.addAll(n.to()));
        return List.copyOf(new LinkedHashSet<>(told));
    }

    /** @return {@code a} with the Mail Manager's latest word on each message not finished yet */
    Alert refresh(Alert a) {
        return refresh(a, null);
    }

    /**
     * @param at the platform time: a channel message of a named contact that failed later (an SMS gammu-smsd moved to
     *           {@code error/}) is then followed by the contact's next channels at once; null = no fallback
     */
    Alert refresh(Alert a, Instant at) {
        if (a.notifications().stream().noneMatch(Notifier::unfinished)) {
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
                        .equals(n.channel()) && contacts.get(Words.who(n.to())).map(ContactBook.Contact::plain)
                        .orElse(true) ? "" : " to " + Words.who(n.to()) + " by " + ChannelSender.word(n.channel()));
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
            failedLater.forEach(n -> now.addAll(late.after(a, n, now, at, toldSoFar(a))));
        }
        return !changed ? a : Copies.notifications(a, now, a.contactsReached());
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

    private static boolean unfinished(Notification n) {
        return n.outcome() == MailDelivery.Outcome.QUEUED || n.outcome() == MailDelivery.Outcome.RETRYING
                || n.outcome() == MailDelivery.Outcome.UNKNOWN;
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
