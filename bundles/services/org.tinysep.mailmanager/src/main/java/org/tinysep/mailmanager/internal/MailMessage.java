package org.tinysep.mailmanager.internal;

import java.time.Instant;
import java.util.List;
import java.util.Objects;

/**
 * One queued message and where its delivery stands.
 *
 * @param id           increasing number giving the sending order, also the spool file name
 * @param queuedAt     when {@code send} was called (platform clock)
 * @param pending      the recipients still to deliver to; empty = the configured recipients (nothing tried yet)
 * @param failed       recipients the message could not be delivered to (refused for good or given up)
 * @param firstFailure when (computer clock) the first attempt failed temporarily, or null: the give-up age counts
 *                     from here
 * @param to           the addresses it was sent to; empty = the configured recipients
 */
record MailMessage(long id, Instant queuedAt, String subject, String body, List<String> pending, List<String> failed,
        Instant firstFailure, List<String> to) {

    MailMessage {
        Objects.requireNonNull(queuedAt, "queuedAt");
        subject = subject == null ? "" : subject;
        body = body == null ? "" : body;
        pending = pending == null ? List.of() : List.copyOf(pending);
        failed = failed == null ? List.of() : List.copyOf(failed);
        to = to == null ? List.of() : List.copyOf(to);
    }

    MailMessage(long id, Instant queuedAt, String subject, String body) {
        this(id, queuedAt, subject, body, List.of(), List.of(), null, List.of());
    }

    MailMessage(long id, Instant queuedAt, String subject, String body, List<String> pending, List<String> failed,
            Instant firstFailure) {
        this(id, queuedAt, subject, body, pending, failed, firstFailure, List.of());
    }

    /** @return the recipients of the whole message: {@link #to()}, or the configured ones */
    List<String> recipients(List<String> configured) {
        return to.isEmpty() ? configured : to;
    }

    /** @return this message still to be delivered to {@code remaining}, with failures so far */
    MailMessage retrying(List<String> remaining, List<String> failedNow, Instant firstFailed) {
        return new MailMessage(id, queuedAt, subject, body, remaining, concat(failed, failedNow), firstFailed, to);
    }

    /** @return this message with {@code failedNow} added to its failed recipients */
    MailMessage failing(List<String> failedNow) {
        return new MailMessage(id, queuedAt, subject, body, pending, concat(failed, failedNow), firstFailure, to);
    }

    private static List<String> concat(List<String> a, List<String> b) {
        if (b.isEmpty()) {
            return a;
        }
        java.util.ArrayList<String> all = new java.util.ArrayList<>(a);
        b.stream().filter(x -> !all.contains(x)).forEach(all::add);
        return all;
    }

    @Override
    public String toString() {
        return "mail #" + id + " \"" + subject + "\"";
    }
}
