package org.tinysep.inactivity.internal;

import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.MailManagerProvider;

/** Calls for help: mails each alert exactly once, through the first Mail Manager present. */
final class HelpCall {

    /** What became of a call. */
    enum Outcome { SENT, ALREADY_SENT, NO_MAIL_MANAGER }

    private final AlertMail words;
    private final Map<String, MailManagerProvider> mailers = new ConcurrentHashMap<>();
    private InactivityAlert sent;

    HelpCall(AlertMail words) {
        this.words = words;
    }

    void add(MailManagerProvider m) {
        mailers.put(m.deviceUid(), m);
    }

    void remove(String uid) {
        mailers.remove(uid);
    }

    /** Mails {@code alert} unless it was mailed already; {@code send} never blocks (MailManagerProvider). */
    synchronized Outcome call(InactivityAlert alert) {
        Objects.requireNonNull(alert, "alert");
        if (alert.equals(sent)) {
            return Outcome.ALREADY_SENT;
        }
        MailManagerProvider m = mailers.values().stream().findFirst().orElse(null);
        if (m == null) {
            return Outcome.NO_MAIL_MANAGER;
        }
        sent = alert;
        m.send(words.subject(alert), words.body(alert));
        return Outcome.SENT;
    }

    String subject(InactivityAlert alert) {
        return words.subject(alert);
    }
}
