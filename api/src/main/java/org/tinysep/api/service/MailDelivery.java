package org.tinysep.api.service;

import java.time.Instant;
import java.util.List;
import java.util.Objects;

/**
 * What became of one message handed to the Mail Manager.
 *
 * @param id       the Mail Manager's id of the message (as returned by {@link MailManagerProvider#sendTo})
 * @param subject  its subject
 * @param to       its recipients
 * @param queuedAt when it was handed over (platform time)
 * @param outcome  where it stands
 * @param detail   in plain words: to whom it was delivered, the server's reply, the next try
 * @param at       when the outcome last changed
 * @since 1.1
 */
public record MailDelivery(String id, String subject, List<String> to, Instant queuedAt, Outcome outcome,
        String detail, Instant at) {

    /** Where a message stands. */
    public enum Outcome {
        /** Handed over, not tried yet. */
        QUEUED,
        /** The server took it for every recipient. */
        SENT,
        /** An attempt failed temporarily; it is tried again. */
        RETRYING,
        /** Not delivered to some recipients: refused for good or given up. */
        FAILED,
        /** No SMTP host configured: written to the log only. */
        LOGGED_ONLY,
        /** Nothing is known about it (e.g. forgotten after a restart of the Mail Manager). */
        UNKNOWN
    }

    public MailDelivery {
        Objects.requireNonNull(id, "id");
        subject = subject == null ? "" : subject;
        to = to == null ? List.of() : List.copyOf(to);
        Objects.requireNonNull(queuedAt, "queuedAt");
        Objects.requireNonNull(outcome, "outcome");
        detail = detail == null ? "" : detail;
        Objects.requireNonNull(at, "at");
    }
}
