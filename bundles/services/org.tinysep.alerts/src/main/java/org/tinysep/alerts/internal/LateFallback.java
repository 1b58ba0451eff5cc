package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.channel.ChannelMessage;

/**
 * A channel message that failed after it was handed over (an SMS gammu-smsd moved to {@code error/}): the contact's
 * channels after that one are tried at once, unless the contact was tried again since.
 */
final class LateFallback {

    private final ContactBook contacts;
    private final ChannelSender sender;
    private final AlertText words;
    private final Consumer<String> events;
    private final Consumer<String> problems;

    LateFallback(ContactBook contacts, ChannelSender sender, AlertText words, Consumer<String> events,
            Consumer<String> problems) {
        this.contacts = contacts;
        this.sender = sender;
        this.words = words;
        this.events = events;
        this.problems = problems;
    }

    /** @return the subject of {@code a}'s message of {@code step} sent at {@code at} */
    static String subject(AlertText words, Alert a, NotificationStep step, Instant at) {
        return switch (step) {
            case FIRST -> words.firstSubject(a);
            case REPEAT -> words.repeatSubject(a, at);
            case ESCALATION -> words.escalationSubject(a, at);
            case ALL_CLEAR -> words.allClearSubject(a);
        };
    }

    /** @return the attempts on the channels after {@code failed}'s, when it was the contact's last attempt so far */
    List<Notification> after(Alert a, Notification failed, List<Notification> all, Instant at, List<String> told) {
        Optional<ContactBook.Contact> c = failed.to().size() == 1 ? contacts.get(failed.to().get(0))
                .filter(x -> !x.plain()) : Optional.empty();
        if (c.isEmpty() || all.indexOf(failed) < 0 || all.subList(all.indexOf(failed) + 1, all.size()).stream()
                .anyMatch(x -> x.to().equals(failed.to()))) {
            return List.of(); // a plain address, or the contact was tried again since
        }
        List<ContactBook.Address> rest = c.get().addresses();
        int i = rest.stream().map(ContactBook.Address::scheme).toList().indexOf(failed.channel());
        if (i < 0 || i + 1 >= rest.size()) {
            return List.of();
        }
        ContactBook.Contact next = new ContactBook.Contact(c.get().key(), rest.subList(i + 1, rest.size()), false);
        String subject = subject(words, a, failed.step(), at);
        ChannelSender.Reach r = sender.reach(next, at, failed.step(), subject, words.body(a, told, at),
                new ChannelMessage(a.id(), subject, "Not acknowledged yet. Reply OK " + a.id() + " if you take care "
                        + "of it."));
        (r.reached() ? events : problems).accept("alert " + a.id() + ": " + ChannelSender.word(failed.channel())
                + " to " + next.key() + " failed, so the " + failed.step().name().toLowerCase().replace('_', ' ')
                + " message went on " + r.words());
        return r.tried();
    }
}
