package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.List;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogQuery;

/**
 * The alert service's event-log entries (origin {@value #ORIGIN}). The console (SLF4J at INFO) gets one line per
 * alert, when it is raised ({@link #raised}); acknowledgements, all clears and the rest go to the event log only
 * (SLF4J at DEBUG), so the console stays quiet. Problems are warnings on both.
 */
final class AlertLog {

    static final String ORIGIN = "Alerts";
    private static final Logger LOG = LoggerFactory.getLogger(AlertLog.class);

    private volatile EventLog eventLog;

    void use(EventLog log) {
        eventLog = log;
    }

    void gone(EventLog log) {
        if (eventLog == log) {
            eventLog = null;
        }
    }

    /** A new alert: the one console line it gets, and an event-log entry. */
    void raised(String text) {
        LOG.info("Alerts: {} (tinysep:alerts shows it; repeats and the all clear go to the event log)", text);
        record(EventKind.DEVICE_EVENT, text);
    }

    /** Anything else that happens to an alert: the event log only (the console at DEBUG). */
    void event(String text) {
        LOG.debug("Alerts: {}", text);
        record(EventKind.DEVICE_EVENT, text);
    }

    void problem(String text) {
        LOG.warn("Alerts: {}", text);
        record(EventKind.PROBLEM, text);
    }

    /**
     * @return the caregiver signals ({@link NoticeFeed#isSignal}) recorded from {@code from} to {@code to}, oldest
     *         first, at most 50; null when there is no event log to ask
     */
    List<EventEntry> signals(Instant from, Instant to) {
        EventLog log = eventLog;
        if (log == null) {
            return null;
        }
        try {
            return log.query(new LogQuery(from, to, Set.of(), Set.of(EventKind.PROBLEM.name()), 10_000)).entries()
                    .stream().filter(NoticeFeed::isSignal).limit(50).toList();
        } catch (RuntimeException e) { // the log going away: the summary still goes out
            return null;
        }
    }

    private void record(EventKind kind, String text) {
        EventLog log = eventLog;
        if (log != null) {
            log.record(kind, ORIGIN, text);
        }
    }
}
