package org.tinysep.alerts.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;

/**
 * Picks the caregiver-visible signals out of the event log (the shared contract of docs/security.md, "Nothing
 * reduces monitoring in silence": a {@code PROBLEM} entry whose message starts with {@value #REDUCED} or
 * {@value #MISMATCH}) and decides which of them are mailed:
 * each entry once (by sequence number), and the same message not again within {@code quiet} (a burst of one cause
 * is one notice). Not thread-safe: one poller uses it.
 */
final class NoticeFeed {

    static final String REDUCED = "Monitoring reduced: ";
    static final String MISMATCH = "Node type mismatch: ";

    private final Duration quiet;
    private final Map<String, Instant> mailed = new HashMap<>();
    private long last;

    /** @param last the sequence number of the last entry already handled (0: none) */
    NoticeFeed(long last, Duration quiet) {
        this.last = last;
        this.quiet = quiet;
    }

    /** @return whether {@code e} is a signal for the caregivers */
    static boolean isSignal(EventEntry e) {
        return e.kind() == EventKind.PROBLEM && (e.message().startsWith(REDUCED) || e.message().startsWith(MISMATCH));
    }

    /** @return the sequence number of the last entry handled */
    long last() {
        return last;
    }

    /**
     * @param recent the newest entries of the log, oldest first
     * @return whether {@code recent} reaches back to the last entry handled (else the caller asks for more)
     */
    boolean covers(List<EventEntry> recent) {
        return recent.isEmpty() || recent.get(0).sequence() <= last + 1;
    }

    /**
     * Takes the signals after the last entry handled and marks everything in {@code recent} handled. A log that
     * starts again (its newest sequence below the last handled, e.g. a new state folder) is read from its start.
     *
     * @return the signals to mail now: new ones, less the messages mailed within the quiet period
     */
    List<EventEntry> take(List<EventEntry> recent) {
        if (recent.isEmpty()) {
            return List.of();
        }
        long newest = recent.get(recent.size() - 1).sequence();
        if (newest < last) {
            last = 0;
        }
        List<EventEntry> out = new ArrayList<>();
        for (EventEntry e : recent) {
            if (e.sequence() <= last || !isSignal(e)) {
                continue;
            }
            Instant before = mailed.get(e.message());
            if (before == null || !e.time().isBefore(before.plus(quiet))) {
                mailed.put(e.message(), e.time());
                out.add(e);
            }
        }
        last = newest;
        mailed.values().removeIf(t -> t.plus(quiet).isBefore(recent.get(recent.size() - 1).time()));
        return out;
    }
}
