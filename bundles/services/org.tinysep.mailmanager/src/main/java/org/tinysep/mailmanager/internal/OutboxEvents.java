package org.tinysep.mailmanager.internal;

import java.util.List;
import org.tinysep.api.service.MailStatus;

/** What the {@link Outbox} tells its device; every call comes on the outbox thread. */
interface OutboxEvents {
    void statusChanged(MailStatus status, String detail);

    void queued(MailMessage m, List<String> recipients);

    void delivered(MailMessage m, List<String> recipients);

    /** An attempt failed temporarily; {@code what} says for whom, why and when the next try comes. */
    void retrying(MailMessage m, String what);

    /** A message could not be delivered to some recipients, for good; {@code what} says to whom and why. */
    void failed(MailMessage m, String what);

    /**
     * @param notice why an alert was not delivered (kept until a message is delivered to all its recipients), or
     *               null when the last finished message was delivered to everybody
     */
    void undelivered(String notice);

    /** A message written to the log only (not configured). */
    void logged(MailMessage m);

    void problem(String message);

    /** A security warning in plain words (how the password is kept). */
    void warning(String message);
}
