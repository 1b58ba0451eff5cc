package org.tinysep.inactivity.internal;

import java.io.IOException;
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
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.Sighting;

/**
 * Starts learning from the event log's history on disk, so learning survives restarts and begins with the logs a
 * home already has: the activity entries of the sensor devices (movement detected, doors and windows opened or
 * closed; "no movement" is not an activity live either) and Flat Occupancy's decisions (the times the flat was empty). A device's entries count once
 * it is one of Inactivity Recognition's sources; until then (its bus device not yet back after a restart) they
 * wait. A flush or appliance turning OFF while the person was last seen in another room is the device finishing by
 * itself, not activity, as it is live ({@link ActivityFactory#finishedByItself}): such an entry remembers the device
 * of the activity before it and is judged once both devices are sources (their rooms known). Thread-safe.
 */
final class HistoryFromLog {

    /** At most this many entries are read (the newest; sensors log changes only, a home logs far fewer a month). */
    static final int MAX_ENTRIES = 500_000;

    private static final Set<String> ACTIVITY = Set.of("movement detected", "door opened",
            "door closed", "window opened", "window closed", "bed on", "bed off", "seat on", "seat off",
            "flush on", "flush off", "appliance on", "appliance off", "other on", "other off");

    /**
     * A waiting activity entry: when, which device, whether it was a bed ("bed on") or seat mat turning ON, and
     * whether a bed mat turned OFF ("bed off": the person got up, which ends sleep also in the bedroom at night).
     *
     * @param off   for a flush or appliance turning OFF ("flush off", "appliance off"): its kind, else null
     * @param after for such an entry: the device of the last activity before it (which the person made), else null
     */
    record Raw(Instant at, String device, boolean inBed, boolean seated, boolean upFromBed, PresenceKind off,
            String after) {
        /** An entry that is no flush or appliance turning OFF. */
        Raw(Instant at, String device, boolean inBed, boolean seated, boolean upFromBed) {
            this(at, device, inBed, seated, upFromBed, null, null);
        }

        /** An entry that is no bed mat turning OFF, nor a flush or appliance turning OFF. */
        Raw(Instant at, String device, boolean inBed, boolean seated) {
            this(at, device, inBed, seated, false);
        }
    }

    private final HistoryLearner learner;
    private final List<Raw> pending = new ArrayList<>();
    private boolean loaded;
    private int finished;

    HistoryFromLog(HistoryLearner learner) {
        this.learner = learner;
    }

    /**
     * Reads the entries from {@code days} before {@code now} on, <b>with no upper bound</b>: at activation the
     * platform's clock may still be behind the log (an EXTERNAL Time Controller holds the wall clock until its first
     * tick, which jumps to the virtual time the log was written in; a clock that went back). Bounding the query by
     * that {@code now} would read nothing in such a case (a replayed history would be lost, and the
     * learned detector would never leave its cold start). The learner drops what is older than its history window
     * at the time it learns ({@link HistoryLearner#profile}).
     *
     * @return a sentence for the event log: what was read
     */
    String load(EventLog log, Instant now, int days) {
        return load(log, now, days, null);
    }

    /**
     * As {@link #load(EventLog, Instant, int)}, but first from the detector's own memory (the
     * event log rotates, and a flood of other entries could rotate all it learned from away): what the memory
     * holds is learned from, and the event log is read only after the time it was saved, to fill what it lacks.
     *
     * @param log    the event log, or null when there is none
     * @param memory the detector's own memory, or null
     */
    String load(EventLog log, Instant now, int days, LearnedMemory memory) {
        Instant from = now.minus(Duration.ofDays(days));
        String remembered = "";
        if (memory != null) {
            try {
                LearnedMemory.Content c = memory.load();
                if (c != null) {
                    learner.remember(c.memory());
                    synchronized (this) {
                        pending.addAll(c.pending());
                    }
                    from = c.covered() == null ? from : latest(c.covered(), c.memory(), c.pending()).plusNanos(1);
                    remembered = "learning from its own memory (" + c.memory().sightings().size() + " activities, "
                            + (c.damaged() > 0 ? c.damaged() + " damaged lines skipped, " : "") + "saved at "
                            + c.covered() + ") and ";
                }
            } catch (IOException | RuntimeException e) {
                remembered = "its own memory " + memory.file() + " could not be read (" + e.getMessage()
                        + "); learning from ";
            }
        }
        String said = log == null ? "live activity only (no event log)" : readLog(log, from);
        synchronized (this) {
            loaded = true;
        }
        learner.loaded();
        return (remembered.isEmpty() ? "learning from " : remembered) + said;
    }

    /**
     * Saves what the learner remembers (and the logged activities still waiting for their device) atomically in
     * {@code memory}, as covering the history up to {@code now}; nothing before {@link #load} finished.
     *
     * @return whether it was saved
     */
    boolean save(LearnedMemory memory, Instant now) throws IOException {
        List<Raw> waiting;
        synchronized (this) {
            if (!loaded) {
                return false;
            }
            waiting = List.copyOf(pending);
        }
        HistoryLearner.Memory m = learner.memory();
        memory.save(m, waiting, latest(now, m, waiting));
        return true;
    }

    /**
     * What the memory covers: the later of the clock and the newest time it holds. The clock when saving can be
     * behind the history (the platform stopping after its Time Controller, which held virtual time, fell back to the
     * wall clock; a clock that went back): the log read from that clock on would hand the same activities to the
     * learner a second time (issue 28, session 33: Ordonez B's platform learned its history twice, and the
     * duplicates, 0 s apart, counted as quiet periods towards shortening a limit).
     */
    static Instant latest(Instant clock, HistoryLearner.Memory m, List<Raw> waiting) {
        Instant t = clock;
        for (Sighting s : m.sightings()) {
            t = s.at().isAfter(t) ? s.at() : t;
        }
        for (var a : m.away()) {
            t = a.to().isAfter(t) ? a.to() : t;
        }
        t = m.awaySince() != null && m.awaySince().isAfter(t) ? m.awaySince() : t;
        for (Raw r : waiting) {
            t = r.at().isAfter(t) ? r.at() : t;
        }
        return t;
    }

    private String readLog(EventLog log, Instant from) {
        LogHistory<EventEntry> h = log.query(new LogQuery(from, null, Set.of(),
                Set.of(EventKind.DEVICE_EVENT.name()), MAX_ENTRIES));
        int activities = 0;
        int occupancy = 0;
        synchronized (this) {
            // the device of the last activity the person made: a flush or appliance OFF never moves it (live, such
            // an OFF is either in the person's room, or not counted); null before the first entry read
            String person = null;
            for (EventEntry e : h.entries()) {
                String m = e.message();
                if (ACTIVITY.contains(m) || m.startsWith("movement detected at ")) {
                    PresenceKind off = switch (m) {
                        case "flush off" -> PresenceKind.FLUSH;
                        case "appliance off" -> PresenceKind.APPLIANCE;
                        default -> null;
                    };
                    pending.add(new Raw(e.time(), e.origin(), m.equals("bed on"), m.equals("seat on"),
                            m.equals("bed off"), off, off == null ? null : person));
                    person = off == null || person == null ? e.origin() : person;
                    activities++;
                } else if (m.startsWith("flat unoccupied (") || m.startsWith("flat occupied (")) {
                    learner.occupancy(m.startsWith("flat unoccupied"), e.time());
                    occupancy++;
                }
            }
        }
        return "the event log's history since " + from + ": " + activities + " activity entries, " + occupancy
                + " occupancy changes" + (h.damagedLines() > 0 ? ", " + h.damagedLines() + " damaged lines skipped" : "");
    }

    /**
     * Hands the waiting entries of devices that are now sources to the learner.
     *
     * A "bed off" entry is handed over as getting up ({@link Sighting#upFromBed()}) whatever the caller made of it,
     * so a night's history read back from the log ends sleep where the live detector did. A flush or appliance
     * turning OFF waits also for the device of the activity before it; when that was in another room, the entry is
     * the device finishing by itself ({@link ActivityFactory#finishedByItself}) and is dropped, as live.
     *
     * @param sighting a device's entry as a sighting, empty while the device is not a source
     * @return how many were handed over
     */
    synchronized int resolve(Function<Raw, Optional<Sighting>> sighting) {
        int n = 0;
        for (var it = pending.iterator(); it.hasNext();) {
            Raw raw = it.next();
            Optional<Sighting> s = sighting.apply(raw).map(x -> raw.upFromBed() && !x.upFromBed()
                    ? new Sighting(x.at(), x.room(), x.roomName(), x.roomType(), x.inBed(), x.seated(), true) : x);
            if (s.isEmpty()) {
                continue;
            }
            if (raw.after() != null) {
                Optional<Sighting> before = sighting.apply(new Raw(raw.at(), raw.after(), false, false));
                if (before.isEmpty()) {
                    continue; // the room of the activity before it is not known yet
                }
                if (ActivityFactory.finishedByItself(raw.off(), false, s.get().room(), before.get().room())) {
                    it.remove();
                    finished++;
                    continue;
                }
            }
            learner.add(s.get());
            it.remove();
            n++;
        }
        if (n > 0) {
            learner.loaded();
        }
        return n;
    }

    /** @return how many logged flush or appliance OFF entries were dropped as the device finishing by itself */
    synchronized int finishedByItself() {
        return finished;
    }

    synchronized boolean hasPending() {
        return !pending.isEmpty();
    }
}
