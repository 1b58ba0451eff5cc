package org.tinysep.alerts.internal;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/** The alert service's event-log entries (origin {@value #ORIGIN}), also written to SLF4J. */
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

    void event(String text) {
        LOG.info("Alerts: {}", text);
        record(EventKind.DEVICE_EVENT, text);
    }

    void problem(String text) {
        LOG.warn("Alerts: {}", text);
        record(EventKind.PROBLEM, text);
    }

    private void record(EventKind kind, String text) {
        EventLog log = eventLog;
        if (log != null) {
            log.record(kind, ORIGIN, text);
        }
    }
}
