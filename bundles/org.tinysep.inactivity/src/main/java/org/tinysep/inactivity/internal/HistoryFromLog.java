package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.Sighting;

/**
 * Starts learning from the event log's history on disk, so learning survives restarts and begins with the logs a
 * home already has: the activity entries of the sensor devices (movement detected, doors and windows opened or
 * closed; "no movement" is not an activity live either) and Flat Occupancy's decisions (the times the flat was empty). A device's entries count once
 * it is one of Inactivity Recognition's sources; until then (its bus device not yet back after a restart) they
 * wait. Thread-safe.
 */
final class HistoryFromLog {

    /** At most this many entries are read (the newest; sensors log changes only, a home logs far fewer a month). */
    static final int MAX_ENTRIES = 500_000;

    private static final Set<String> ACTIVITY = Set.of("movement detected", "door opened",
            "door closed", "window opened", "window closed", "bed on", "bed off", "seat on", "seat off",
            "flush on", "flush off", "appliance on", "appliance off", "other on", "other off");

    /** A waiting activity entry: when, which device, and whether it was a bed ("bed on") or seat mat turning ON. */
    record Raw(Instant at, String device, boolean inBed, boolean seated) {
    }

    private final HistoryLearner learner;
    private final List<Raw> pending = new ArrayList<>();

    HistoryFromLog(HistoryLearner learner) {
        this.learner = learner;
    }

    /**
     * Reads the entries from {@code days} before {@code now} on, <b>with no upper bound</b>: at activation the
     * platform's clock may still be behind the log (an EXTERNAL Time Controller holds the wall clock until its first
     * tick, which jumps to the virtual time the log was written in; a clock that went back). Bounding the query by
     * that {@code now} read nothing in such a case (issue 11: every replayed history was lost, so the learned
     * detector never left its cold start). The learner drops what is older than its history window at the time it
     * learns ({@link HistoryLearner#profile}).
     *
     * @return a sentence for the event log: what was read
     */
    String load(EventLog log, Instant now, int days) {
        LogHistory<EventEntry> h = log.query(new LogQuery(now.minus(Duration.ofDays(days)), null, Set.of(),
                Set.of(EventKind.DEVICE_EVENT.name()), MAX_ENTRIES));
        int activities = 0;
        int occupancy = 0;
        synchronized (this) {
            for (EventEntry e : h.entries()) {
                String m = e.message();
                if (ACTIVITY.contains(m) || m.startsWith("movement detected at ")) {
                    pending.add(new Raw(e.time(), e.origin(), m.equals("bed on"), m.equals("seat on")));
                    activities++;
                } else if (m.startsWith("flat unoccupied (") || m.startsWith("flat occupied (")) {
                    learner.occupancy(m.startsWith("flat unoccupied"), e.time());
                    occupancy++;
                }
            }
        }
        learner.loaded();
        return "learning from the event log's history since " + now.minus(Duration.ofDays(days)) + ": "
                + activities + " activity entries, " + occupancy + " occupancy changes"
                + (h.damagedLines() > 0 ? ", " + h.damagedLines() + " damaged lines skipped" : "");
    }

    /**
     * Hands the waiting entries of devices that are now sources to the learner.
     *
     * @param sighting a device's entry as a sighting, empty while the device is not a source
     * @return how many were handed over
     */
    synchronized int resolve(Function<Raw, Optional<Sighting>> sighting) {
        int n = 0;
        for (var it = pending.iterator(); it.hasNext();) {
            Optional<Sighting> s = sighting.apply(it.next());
            if (s.isPresent()) {
                learner.add(s.get());
                it.remove();
                n++;
            }
        }
        if (n > 0) {
            learner.loaded();
        }
        return n;
    }

    synchronized boolean hasPending() {
        return !pending.isEmpty();
    }
}
