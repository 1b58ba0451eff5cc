package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
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
    private boolean saidNoMail;
    /** What a queued message's entry adds: it is not delivered yet, and where the outcome will be told. */
    static final String QUEUED_NOTE = " (not delivered yet: its delivery or failure is logged when the Mail Manager "
            + "reports it)";

    Notifier(AlertSettings settings, Words words, Supplier<MailManagerProvider> mail, Consumer<String> events,
            Consumer<String> problems) {
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
        String subject = switch (step.step()) {
            case FIRST -> words.firstSubject(a);
            case REPEAT -> words.repeatSubject(a, now);
            case ESCALATION -> words.escalationSubject(a, now);
            case ALL_CLEAR -> words.allClearSubject(a);
        };
        List<String> told = step.step() == NotificationStep.ESCALATION ? union(toldSoFar(a), step.to()) : toldSoFar(a);
        Optional<Notification> n = hand(now, step.step(), step.to(), subject, words.body(a, told, now));
        if (n.isEmpty()) {
            if (!saidNoMail) {
                saidNoMail = true;
                problems.accept("alert " + a.id() + ": no Mail Manager to send its " + step.step().name()
                        .toLowerCase().replace('_', ' ') + " message; it is sent as soon as one is there");
            }
            return a;
        }
        saidNoMail = false;
        // the Mail Manager only queued it: say so; what became of it is logged when the Mail Manager knows (refresh)
        events.accept(switch (step.step()) {
            case FIRST -> "alert " + a.id() + ": first message queued to the Mail Manager for " + Words.who(step.to());
            case REPEAT -> "alert " + a.id() + " not acknowledged: repeat queued to the Mail Manager for "
                    + Words.who(step.to());
            case ESCALATION -> "alert " + a.id() + " not acknowledged: passed on to the next contact, "
                    + Words.who(step.to()) + " (contact " + step.reached() + " of " + settings.contacts().size()
                    + "), message queued to the Mail Manager";
            case ALL_CLEAR -> "alert " + a.id() + ": all clear queued to the Mail Manager for " + Words.who(step.to());
        } + QUEUED_NOTE);
        return Copies.plus(a, n.get(), step.reached());
    }

    /** @return {@code cleared} with an all-clear message to everyone told of it (when a Mail Manager is there) */
    Alert allClear(Alert cleared, String why, Instant now) {
        if (cleared.notifications().isEmpty()) {
            return cleared; // nobody was told: nobody needs the all clear
        }
        List<String> to = toldSoFar(cleared);
        Optional<Notification> n = hand(now, NotificationStep.ALL_CLEAR, to, words.allClearSubject(cleared),
                words.allClearBody(cleared, why));
        if (n.isEmpty()) {
            problems.accept("alert " + cleared.id() + ": no Mail Manager to send the all clear (" + why + ")");
            return cleared;
        }
        return Copies.plus(cleared, n.get(), cleared.contactsReached());
    }

    /** @return everyone told of {@code a} so far (empty = the Mail Manager's recipients) */
    List<String> toldSoFar(Alert a) {
        List<String> told = new ArrayList<>();
        a.notifications().forEach(n -> told.addAll(n.to()));
        return List.copyOf(new LinkedHashSet<>(told));
    }

    /** @return {@code a} with the Mail Manager's latest word on each message not finished yet */
    Alert refresh(Alert a) {
        MailManagerProvider m = mail.get();
        if (m == null || a.notifications().stream().noneMatch(Notifier::unfinished)) {
            return a;
        }
        List<Notification> now = new ArrayList<>();
        boolean changed = false;
        for (Notification n : a.notifications()) {
            Optional<MailDelivery> d = unfinished(n) && !n.mailId().isEmpty() ? m.delivery(n.mailId())
                    : Optional.empty();
            if (d.isPresent() && (d.get().outcome() != n.outcome() || !d.get().detail().equals(n.detail()))) {
                now.add(n.with(d.get().outcome(), d.get().detail()));
                changed = true;
                if (d.get().outcome() == MailDelivery.Outcome.SENT) {
                    events.accept("alert " + a.id() + ": its " + n.step().name().toLowerCase().replace('_', ' ')
                            + " message was delivered (" + d.get().detail() + ")");
                }
                if (d.get().outcome() == MailDelivery.Outcome.FAILED) {
                    problems.accept("alert " + a.id() + ": its " + n.step().name().toLowerCase().replace('_', ' ')
                            + " message was NOT delivered: " + d.get().detail());
                }
            } else {
                now.add(n);
            }
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

    private static List<String> union(List<String> a, List<String> b) {
        Set<String> all = new LinkedHashSet<>(a);
        all.addAll(b);
        return List.copyOf(all);
    }
}
