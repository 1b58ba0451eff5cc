package org.tinysep.drivers.internal;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/** Where the drivers list tells the user what it did and what went wrong: the log and the platform's event log. */
final class Report {

    /** The event-log origin of every entry. */
    static final String ORIGIN = "drivers-list";
    private static final Logger LOG = LoggerFactory.getLogger(Report.class);

    private final EventLog events;

    Report(EventLog events) {
        this.events = events;
    }

    /** Something the list changed (installed, started, stopped, uninstalled, added, removed, moved). */
    void change(String what) {
        LOG.info("Drivers list: {}", what);
        events.record(EventKind.STATUS, ORIGIN, what);
    }

    /** Something that went wrong; the platform goes on. */
    void problem(String what) {
        LOG.warn("Drivers list: {}", what);
        events.record(EventKind.PROBLEM, ORIGIN, what);
    }

    /** Each change line, as a problem when it says the list could not do something. */
    void changes(Iterable<String> lines) {
        for (String line : lines) {
            if (line.startsWith("cannot ") || line.startsWith("missing ")) {
                problem(line);
            } else {
                change(line);
            }
        }
    }
}
