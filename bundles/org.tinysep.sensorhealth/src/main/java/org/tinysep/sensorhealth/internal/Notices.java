package org.tinysep.sensorhealth.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.health.SensorHealth;

/**
 * Which notices are due, one tick at a time: a sensor seen OFFLINE for {@code delay} gets one "offline" notice per
 * silence, and a "back" notice when it is heard again after that; a low battery gets one notice per low period.
 * A sensor back before the delay sends nothing. The delay counts from when the platform first saw the sensor
 * OFFLINE (after a restart its last frame may be days old). Pure logic, not thread-safe (the platform tick calls
 * it).
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
    private final Set<String> noticed = new HashSet<>();
    private final Set<String> batteryNoticed = new HashSet<>();

    Notices(Duration delay) {
        this.delay = delay;
    }

    /** @return the notices due now for these sensors (every known sensor, every tick) */
    List<Notice> due(List<SensorHealth> sensors, Instant now) {
        List<Notice> out = new ArrayList<>();
        Set<String> present = new HashSet<>();
        for (SensorHealth s : sensors) {
            String uid = s.node().deviceUid();
            present.add(uid);
            if (!s.node().online()) {
                Silence silence = offline.computeIfAbsent(uid, u -> new Silence(sinceOf(s, now), now));
                if (!noticed.contains(uid) && !now.isBefore(silence.seen().plus(delay))) {
                    noticed.add(uid);
                    out.add(new Notice(Kind.OFFLINE, s, silence.since()));
                }
            } else if (offline.remove(uid) != null && noticed.remove(uid)) {
                out.add(new Notice(Kind.BACK, s, now));
            }
            if (s.node().batteryLow()) {
                if (batteryNoticed.add(uid)) {
                    out.add(new Notice(Kind.LOW_BATTERY, s, now));
                }
            } else {
                batteryNoticed.remove(uid);
            }
        }
        offline.keySet().retainAll(present); // removed devices are forgotten
        noticed.retainAll(present);
        batteryNoticed.retainAll(present);
        return out;
    }

    private static Instant sinceOf(SensorHealth s, Instant now) {
        Instant silent = s.node().silentSince();
        if (silent != null && !silent.equals(Instant.EPOCH)) {
            return silent;
        }
        return s.node().lastHeard() != null ? s.node().lastHeard() : now;
    }
}
