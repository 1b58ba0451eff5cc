package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Calls for help: hands each alert exactly once to the alert service when one is running (bundle
 * {@code org.tinysep.alerts}: it keeps the alert open until acknowledged, repeats and escalates it, and sends the
 * all clear), else to the first Mail Manager present (which queues and delivers it, and logs the delivery). An
 * alert handed over before a restart, raised again after it, is not handed over twice.
 */
final class HelpCall {

    /** The source the alert service knows Inactivity Recognition's alerts by (its all clear matches it). */
    static final String SOURCE = "inactivity";

    /** What became of a call. */
    enum Outcome { HANDED_OVER, HANDED_TO_ALERT_SERVICE, ALREADY_HANDED_OVER, NO_MAIL_MANAGER }

    private final AlertMail words;
    private final Map<String, MailManagerProvider> mailers = new ConcurrentHashMap<>();
    private InactivityAlert sent;
    /** When the alert handed over last was due (kept in the backup), or null. */
    private volatile Instant handedOverDue;
    private volatile Outage outage;
    /** Whether the last hand-over went to the alert service. */
    private volatile boolean toService;

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
        toService = toAlertService(alert);
        if (toService) {
            sent = alert;
            handedOverDue = alert.raisedAt();
            return Outcome.HANDED_TO_ALERT_SERVICE;
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

    /** @return whether an alert service took the alert (false outside a framework or without one) */
    private boolean toAlertService(InactivityAlert alert) {
        Bundle bundle = FrameworkUtil.getBundle(HelpCall.class);
        BundleContext context = bundle == null ? null : bundle.getBundleContext();
        if (context == null) {
            return false;
        }
        try {
            ServiceReference<AlertService> ref = context.getServiceReference(AlertService.class);
            AlertService service = ref == null ? null : context.getService(ref);
            if (service == null) {
                return false;
            }
            try {
                service.raise(new AlertRequest(AlertKind.INACTIVITY, SOURCE, alert.roomUid(), alert.roomName(),
                        alert.raisedAt(), subject(alert), words.body(alert, outage)));
                return true;
            } finally {
                context.ungetService(ref);
            }
        } catch (RuntimeException e) { // stopping, or the alert service failed: the Mail Manager, if any, takes it
            return false;
        }
    }

    /** @return for the event log: to whom the last call handed {@code alert}, and its subject */
    String outcomeWords(InactivityAlert alert) {
        return (toService ? "alert handed to the alert service (it tells the contacts, repeats and escalates until "
                + "someone acknowledges): " : "alert handed to the Mail Manager (it queues, sends and logs the "
                + "delivery): ") + subject(alert);
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
