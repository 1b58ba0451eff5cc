package org.tinysep.mailmanager.internal;

import org.tinysep.api.service.MailStatus;

/** What the {@link Outbox} tells its device; every call comes on the outbox thread. */
interface OutboxEvents {
    void statusChanged(MailStatus status, String detail);

    void queued(MailMessage m);

    void sent(MailMessage m, String detail);

    void givenUp(MailMessage m, String reason);

    /** A message written to the log only (not configured). */
    void logged(MailMessage m);

    void problem(String message);
}
