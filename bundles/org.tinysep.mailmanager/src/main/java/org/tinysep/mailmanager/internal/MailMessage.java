package org.tinysep.mailmanager.internal;

import java.time.Instant;
import java.util.Objects;

/**
 * One queued message.
 *
 * @param id       increasing number giving the sending order, also the spool file name
 * @param queuedAt when {@code send} was called
 */
record MailMessage(long id, Instant queuedAt, String subject, String body) {

    MailMessage {
        Objects.requireNonNull(queuedAt, "queuedAt");
        subject = subject == null ? "" : subject;
        body = body == null ? "" : body;
    }

    @Override
    public String toString() {
        return "mail #" + id + " \"" + subject + "\"";
    }
}
