package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Calls for help: hands each alert exactly once to the first Mail Manager present (which queues and delivers it,
 * and logs the delivery). An alert handed over before a restart, raised again after it, is not handed over twice.
 */
final class HelpCall {

    /** What became of a call. */
    enum Outcome { HANDED_OVER, ALREADY_HANDED_OVER, NO_MAIL_MANAGER }

    private final AlertMail words;
    private final Map<String, MailManagerProvider> mailers = new ConcurrentHashMap<>();
    private InactivityAlert sent;
    /** When the alert handed over last was due (kept in the backup), or null. */
    private volatile Instant handedOverDue;
    private volatile Outage outage;

    HelpCall(AlertMail words) {
        this.words = words;
    }

    void add(MailManagerProvider m) {
        mailers.put(m.deviceUid(), m);
    }

    void remove(String uid) {
        mailers.remove(uid);
    }

    /** Hands {@code alert} over unless it was already; {@code send} never blocks (MailManagerProvider). */
    synchronized Outcome call(InactivityAlert alert) {
        Objects.requireNonNull(alert, "alert");
        if (alert.equals(sent) || alert.raisedAt().equals(handedOverDue)) {
            return Outcome.ALREADY_HANDED_OVER;
        }
        MailManagerProvider m = mailers.values().stream().findFirst().orElse(null);
        if (m == null) {
            return Outcome.NO_MAIL_MANAGER;
        }
        sent = alert;
        handedOverDue = alert.raisedAt();
        m.send(subject(alert), words.body(alert, outage));
        return Outcome.HANDED_OVER;
    }

    /** @return the alert's subject; an alert that fell due while nothing ran says it is late */
    String subject(InactivityAlert alert) {
        return words.subject(alert, outage);
    }

    /** Inactivity Recognition was not running during {@code o} (set after a restart). */
    void outage(Outage o) {
        outage = o;
    }

    /** @return when the alert handed over last was due, or null (for the backup) */
    Instant handedOverDue() {
        return handedOverDue;
    }

    /** Restores {@link #handedOverDue()} after a restart. */
    void handedOverDue(Instant due) {
        handedOverDue = due;
    }
}
