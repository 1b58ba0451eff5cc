package org.tinysep.drivers.internal;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
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

    /**
     * One line for the console instead of every change: the count per kind, e.g. {@code 23 installed, 23 started}
     * (the changes themselves are at DEBUG, the problems among them are reported one by one).
     */
    static String summary(List<String> changes) {
        if (changes.isEmpty()) {
            return "nothing to do";
        }
        Map<String, Integer> counts = new LinkedHashMap<>();
        for (String c : changes) {
            String kind = c.startsWith("cannot ") ? "failed" : c.split(" ", 2)[0];
            counts.merge(kind, 1, Integer::sum);
        }
        StringBuilder s = new StringBuilder();
        counts.forEach((kind, n) -> s.append(s.length() == 0 ? "" : ", ").append(n).append(' ').append(kind));
        return s + " (tinysep:drivers lists them)";
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
