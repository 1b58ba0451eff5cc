package org.tinysep.mqtt.board.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.mqtt.board.internal.Payloads.AlertMessage;
import org.tinysep.mqtt.board.internal.Payloads.Health;
import org.tinysep.mqtt.board.internal.Payloads.Occupancy;
import org.tinysep.mqtt.board.internal.Payloads.Platform;
import org.tinysep.mqtt.board.internal.Payloads.Summary;

/**
 * What the board knows of one flat, from its messages. Bounded: at most {@link #MAX_ALERTS} alerts (cleared ones
 * are forgotten first) and {@link #MAX_DEVICES} devices' health; every text is already cut by {@link Payloads}.
 * Thread-safe: the intake writes, the page reads a {@link #snapshot()}.
 */
final class Flat {

    static final int MAX_ALERTS = 64;
    static final int MAX_DEVICES = 256;
    /** The most a flat's alert {@code seq} may jump above the highest it sent so far (else: refused as implausible). */
    static final long MAX_SEQ_JUMP = 100_000;

    /** An alert as the board shows it: the flat's newest message and what the board did about it. */
    record Entry(AlertMessage alert, Instant received, String ackSentBy, Instant ackSentAt, Instant confirmedAt) { }

    /** A copy of the state, for the page and the status rules. */
    record Snapshot(String id, Instant firstHeard, Instant lastHeard, String status, Instant statusAt,
            Platform platform, Instant heartbeatHeard, Summary summary, Instant summaryHeard, Occupancy occupancy,
            List<Entry> alerts, Map<String, Health> devices, long bad, String lastBad, long duplicates,
            long dropped, String lastWords, Instant lastWordsAt) { }

    private final String id;
    private final Instant firstHeard;
    private Instant lastHeard;
    private String status;
    private Instant statusAt;
    private Platform platform;
    private Instant heartbeatHeard;
    private Summary summary;
    private Instant summaryHeard;
    private Occupancy occupancy;
    private final Map<String, Entry> alerts = new LinkedHashMap<>();
    private final Map<String, Long> forgotten = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Long> eldest) {
            return size() > MAX_ALERTS;
        }
    };
    private final Map<String, Health> devices = new LinkedHashMap<>();
    private long bad;
    private long highestSeq = -1;
    private String lastBad = "";
    private long duplicates;
    private long dropped;
    private String lastWords = "";
    private Instant lastWordsAt;

    Flat(String id, Instant now) {
        this.id = id;
        this.firstHeard = now;
    }

    synchronized void status(String s, Instant at) {
        status = s;
        statusAt = at;
        lastHeard = at; // not "last words": the will itself says nothing about the flat
    }

    synchronized void platform(Platform p, Instant at) {
        platform = p;
        heartbeatHeard = p.heartbeatAt().isBefore(at) ? p.heartbeatAt() : at; // an old retained heartbeat is old
        lastHeard = at; // a heartbeat is not "last words" either: the page shows its time
    }

    synchronized void summary(Summary s, Instant at) {
        summary = s;
        summaryHeard = s.at().isBefore(at) ? s.at() : at;
        heard(at, "daily summary \"" + Payloads.cut(s.text(), 120) + "\"");
    }

    synchronized void occupancy(Occupancy o, Instant at) {
        occupancy = o;
        heard(at, "occupancy " + o.state() + (o.explanation().isEmpty() ? "" : " (" + Payloads.cut(o.explanation(), 120) + ")"));
    }

    /**
     * @return false when the message is a duplicate or older than what the board has (by {@code seq})
     * @throws IllegalArgumentException its {@code seq} jumps more than {@link #MAX_SEQ_JUMP} above the flat's highest
     */
    synchronized boolean alert(AlertMessage a, Instant at) {
        if (highestSeq >= 0 && a.seq() > highestSeq + MAX_SEQ_JUMP) {
            throw new IllegalArgumentException("alert seq " + a.seq() + " jumps more than " + MAX_SEQ_JUMP
                    + " above this flat's highest " + highestSeq + ": ignored");
        }
        Entry old = alerts.get(a.id());
        Long gone = forgotten.get(a.id());
        if ((old != null && old.alert().seq() >= a.seq()) || (old == null && gone != null && gone >= a.seq())) {
            duplicates++;
            return false;
        }
        Instant confirmed = old == null ? null : old.confirmedAt();
        if (a.state().equals("ACKNOWLEDGED") && (old == null || !old.alert().state().equals("ACKNOWLEDGED"))) {
            confirmed = at;
        }
        highestSeq = Math.max(highestSeq, a.seq());
        alerts.remove(a.id());
        alerts.put(a.id(), new Entry(a, at, old == null ? null : old.ackSentBy(), old == null ? null : old.ackSentAt(), confirmed));
        while (alerts.size() > MAX_ALERTS) {
            String victim = alerts.values().stream().filter(e -> e.alert().state().equals("CLEARED"))
                    .map(e -> e.alert().id()).findFirst().orElse(alerts.keySet().iterator().next());
            forget(victim);
        }
        heard(at, "alert \"" + a.title() + "\" " + a.state());
        return true;
    }

    /** The retained alert topic was emptied: the flat is done with it. */
    synchronized void alertGone(String alertId, Instant at) {
        forget(alertId);
        heard(at, "alert " + alertId + " removed");
    }

    synchronized boolean ackSent(String alertId, String by, Instant at) {
        Entry e = alerts.get(alertId);
        if (e == null) {
            return false;
        }
        alerts.put(alertId, new Entry(e.alert(), e.received(), by, at, e.confirmedAt()));
        return true;
    }

    synchronized void health(String uid, Health h, Instant at) {
        if (h == null) {
            devices.remove(uid);
        } else if (devices.containsKey(uid) || devices.size() < MAX_DEVICES) {
            devices.put(uid, h);
        } else {
            dropped++;
            return;
        }
        heard(at, "device " + uid + (h == null ? " removed" : " " + h.status()));
    }

    synchronized void bad(String topic, String reason, Instant at) {
        bad++;
        lastBad = Payloads.cut(topic + ": " + reason, Payloads.MAX_TEXT);
        lastHeard = at;
    }

    synchronized void dropped(long n) {
        dropped += n;
    }

    synchronized Snapshot snapshot() {
        return new Snapshot(id, firstHeard, lastHeard, status, statusAt, platform, heartbeatHeard, summary,
                summaryHeard, occupancy, List.copyOf(new ArrayList<>(alerts.values())), Map.copyOf(devices), bad,
                lastBad, duplicates, dropped, lastWords, lastWordsAt);
    }

    private void forget(String alertId) {
        Entry e = alerts.remove(alertId);
        if (e != null) {
            forgotten.put(alertId, e.alert().seq());
        }
    }

    private void heard(Instant at, String words) {
        lastHeard = at;
        lastWords = Payloads.cut(words, Payloads.MAX_TEXT);
        lastWordsAt = at;
    }
}
