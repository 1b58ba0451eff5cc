package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Calls for help: hands each alert exactly once to the alert service when one is running (bundle
 * {@code org.tinysep.alerts}: it keeps the alert open until acknowledged, repeats and escalates it, and sends the
 * all clear), else to the first Mail Manager present (which queues and delivers it, and logs the delivery). An
 * alert handed over before a restart, raised again after it, is not handed over twice, unless the alert service
 * has no open or acknowledged alert for it any more (it was closed while the person was still quiet): then it is
 * raised again rather than silently lost.
 */
final class HelpCall {

    /** The source the alert service knows Inactivity Recognition's alerts by (its all clear matches it). */
    static final String SOURCE = "inactivity";

    /** What became of a call. */
    enum Outcome { HANDED_OVER, HANDED_TO_ALERT_SERVICE, RAISED_AGAIN, ALREADY_HANDED_OVER, NO_MAIL_MANAGER }

    /** The alert service when one runs: {@code use} applied to it, or empty without one (or when it failed). */
    interface AlertDesk {
        <T> Optional<T> use(Function<AlertService, T> use);
    }

    private final AlertMail words;
    private final AlertDesk desk;
    private final Map<String, MailManagerProvider> mailers = new ConcurrentHashMap<>();
    private InactivityAlert sent;
    /** When the alert handed over last was due (kept in the backup), or null. */
    private volatile Instant handedOverDue;
    private volatile Outage outage;
    /** Whether the last hand-over went to the alert service. */
    private volatile boolean toService;

    HelpCall(AlertMail words) {
        this(words, HelpCall::inFramework);
    }

    HelpCall(AlertMail words, AlertDesk desk) {
        this.words = words;
        this.desk = desk;
    }

    void add(MailManagerProvider m) {
        mailers.put(m.deviceUid(), m);
    }

    void remove(String uid) {
        mailers.remove(uid);
    }

    /** @return a Mail Manager present now, if any (a wearer's own alert goes there without an alert service) */
    Optional<MailManagerProvider> mailer() {
        return mailers.values().stream().findFirst();
    }

    /** Hands {@code alert} over unless it was already; {@code send} never blocks (MailManagerProvider). */
    synchronized Outcome call(InactivityAlert alert) {
        Objects.requireNonNull(alert, "alert");
        boolean again = false;
        if (alert.equals(sent) || alert.raisedAt().equals(handedOverDue)) {
            if (!closedWhileDue(alert)) {
                return Outcome.ALREADY_HANDED_OVER;
            }
            again = true;
        }
        toService = toAlertService(alert);
        if (toService) {
            sent = alert;
            handedOverDue = alert.raisedAt();
            return again ? Outcome.RAISED_AGAIN : Outcome.HANDED_TO_ALERT_SERVICE;
        }
        if (again) {
            return Outcome.ALREADY_HANDED_OVER; // the service went meanwhile: the Mail Manager already had it once
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
        return desk.use(service -> service.raise(new AlertRequest(AlertKind.INACTIVITY, SOURCE, alert.roomUid(),
                alert.roomName(), alert.raisedAt(), subject(alert), words.body(alert, outage)))).isPresent();
    }

    /**
     * @return whether the alert service runs and has neither an open nor an acknowledged alert of this source
     *         raised at {@code alert}'s time: it was handed over, then closed while the person stayed quiet (no one
     *         acknowledged it, no activity cleared it here), so nobody is being told any more
     */
    private boolean closedWhileDue(InactivityAlert alert) {
        return desk.use(service -> service.recent(200).stream().noneMatch(a -> isFor(a, alert)
                && (a.isOpen() || a.state() == AlertState.ACKNOWLEDGED))).orElse(false);
    }

    private static boolean isFor(Alert a, InactivityAlert alert) {
        return SOURCE.equals(a.source()) && alert.raisedAt().equals(a.raisedAt());
    }

    /** The alert service of the framework this class runs in; empty outside one, without one, or when it fails. */
    static <T> Optional<T> inFramework(Function<AlertService, T> use) {
        Bundle bundle = FrameworkUtil.getBundle(HelpCall.class);
        BundleContext context = bundle == null ? null : bundle.getBundleContext();
        if (context == null) {
            return Optional.empty();
        }
        try {
            ServiceReference<AlertService> ref = context.getServiceReference(AlertService.class);
            AlertService service = ref == null ? null : context.getService(ref);
            if (service == null) {
                return Optional.empty();
            }
            try {
                return Optional.ofNullable(use.apply(service));
            } finally {
                context.ungetService(ref);
            }
        } catch (RuntimeException e) { // stopping, or the alert service failed: the Mail Manager, if any, takes it
            return Optional.empty();
        }
    }

    /** @return for the event log: to whom the last call handed {@code alert}, and its subject */
    String outcomeWords(InactivityAlert alert) {
        return outcomeWords(alert, false);
    }

    /** @return {@link #outcomeWords(InactivityAlert)}; {@code again}: it was raised again, and why */
    String outcomeWords(InactivityAlert alert, boolean again) {
        String why = again ? "alert raised again: the alert service had no open alert for it although no activity "
                + "was seen and nobody acknowledged it; " : "";
        return why + (toService ? "alert handed to the alert service (it tells the contacts, repeats and escalates "
                + "until someone acknowledges): " : "alert handed to the Mail Manager (it queues, sends and logs the "
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
