package org.tinysep.sensorhealth.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.device.support.time.Due;

/**
 * Which notices are due, one tick at a time: a sensor seen OFFLINE for {@code delay} gets one "offline" notice per
 * silence, and a "back" notice when it is heard again after that; a low battery gets one notice per low period.
 * A sensor back before the delay sends nothing. The delay counts from when the platform first saw the sensor
 * OFFLINE (after a restart its last frame may be days old). Incremental: it is told only about sensors that are new
 * or whose online/battery state changed ({@link #update}), and a tick looks at the silences still waiting for their
 * notice ({@link #due(Instant)}) only once the first of them is due. Pure logic, not thread-safe (the platform tick
 * calls it).
 */
final class Notices {

    /** A notice to send; {@code since} is when the sensor was last heard (OFFLINE) or the time of the change. */
    record Notice(Kind kind, SensorHealth sensor, Instant since) {
    }

    enum Kind { OFFLINE, BACK, LOW_BATTERY }

    /** A silence being watched. */
    private record Silence(Instant since, Instant seen) {
    }

    private final Duration delay;
    private final Map<String, Silence> offline = new HashMap<>();
    private final Map<String, SensorHealth> waiting = new LinkedHashMap<>(); // offline, notice not yet sent
    private final Set<String> noticed = new HashSet<>();
    private final Set<String> batteryNoticed = new HashSet<>();
    /** When the first waiting silence is due (never later), and the tick before; silences looked at, for tests. */
    private Instant nextDue;
    private Instant lastTick;
    private long looked;

    Notices(Duration delay) {
        this.delay = delay;
    }

    /**
     * A sensor that is new, or whose online or battery state (or its name or room) changed. Notices due at once
     * (back, low battery) are added to {@code out}; an OFFLINE one comes from {@link #due(Instant)}.
     */
    void update(SensorHealth s, Instant now, List<Notice> out) {
        String uid = s.node().deviceUid();
        if (!s.node().online()) {
            Silence silence = offline.computeIfAbsent(uid, u -> new Silence(sinceOf(s, now), now));
            if (!noticed.contains(uid)) {
                waiting.put(uid, s);
                Instant at = silence.seen().plus(delay);
                nextDue = nextDue == null || at.isBefore(nextDue) ? at : nextDue;
            }
        } else {
            waiting.remove(uid);
            if (offline.remove(uid) != null && noticed.remove(uid)) {
                out.add(new Notice(Kind.BACK, s, now));
            }
        }
        if (s.node().batteryLow()) {
            if (batteryNoticed.add(uid)) {
                out.add(new Notice(Kind.LOW_BATTERY, s, now));
            }
        } else {
            batteryNoticed.remove(uid);
        }
    }

    /** A removed sensor is forgotten. */
    void forget(String uid) {
        offline.remove(uid);
        waiting.remove(uid);
        noticed.remove(uid);
        batteryNoticed.remove(uid);
    }

    /** @return the OFFLINE notices due now: only the silences still waiting for theirs are looked at */
    List<Notice> due(Instant now) {
        boolean back = lastTick != null && now.isBefore(lastTick);
        lastTick = now;
        if (waiting.isEmpty() || !back && nextDue != null && now.isBefore(nextDue)) {
            return List.of(); // none waiting, or the first is not due yet
        }
        List<Notice> out = new ArrayList<>();
        Instant next = null;
        for (Iterator<Map.Entry<String, SensorHealth>> i = waiting.entrySet().iterator(); i.hasNext();) {
            Map.Entry<String, SensorHealth> e = i.next();
            Silence silence = offline.get(e.getKey());
            Instant at = silence.seen().plus(delay);
            looked++;
            if (!now.isBefore(at)) {
                i.remove();
                noticed.add(e.getKey());
                out.add(new Notice(Kind.OFFLINE, e.getValue(), silence.since()));
            } else {
                next = Due.earliest(next, at);
            }
        }
        nextDue = next;
        return out;
    }

    /** @return waiting silences looked at by {@link #due(Instant)} since creation */
    long looked() {
        return looked;
    }

    /** @return the notices due now for these sensors, given every known sensor (all of them, each tick) */
    List<Notice> due(List<SensorHealth> sensors, Instant now) {
        List<Notice> out = new ArrayList<>();
        Set<String> present = new HashSet<>();
        for (SensorHealth s : sensors) {
            present.add(s.node().deviceUid());
            update(s, now, out);
        }
        for (String uid : List.copyOf(offline.keySet())) {
            if (!present.contains(uid)) {
                forget(uid);
            }
        }
        batteryNoticed.retainAll(present);
        out.addAll(due(now));
        return out;
    }

    /** @return the number of silences waiting for their notice (looked at each tick) */
    int waiting() {
        return waiting.size();
    }

    private static Instant sinceOf(SensorHealth s, Instant now) {
        Instant silent = s.node().silentSince();
        if (silent != null && !silent.equals(Instant.EPOCH)) {
            return silent;
        }
        return s.node().lastHeard() != null ? s.node().lastHeard() : now;
    }
}
