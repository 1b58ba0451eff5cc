package org.tinysep.mqtt.board.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.tinysep.json.JsonWriter;
import org.tinysep.mqtt.board.internal.Flat.Entry;
import org.tinysep.mqtt.board.internal.Flat.Snapshot;
import org.tinysep.mqtt.board.internal.Liveness.Rules;
import org.tinysep.mqtt.board.internal.Liveness.Verdict;
import org.tinysep.mqtt.board.internal.Payloads.AlertMessage;
import org.tinysep.mqtt.board.internal.Payloads.Health;

/**
 * The board as JSON for its page ({@code GET /board/api/flats}): the link, the totals and every flat, those that
 * need someone first (open alerts, then offline, silent, unknown, online), each state explained in plain words.
 */
final class BoardView {

    private BoardView() {
    }

    static String json(Board board, Rules rules, Instant now, String link, boolean connected) {
        record Row(Snapshot s, Verdict v, long open) { }
        List<Row> rows = new ArrayList<>();
        for (Flat f : board.flats()) {
            Snapshot s = f.snapshot();
            long open = s.alerts().stream().filter(e -> e.alert().state().equals("OPEN")).count();
            rows.add(new Row(s, Liveness.judge(s, rules, now), open));
        }
        rows.sort(Comparator.comparing((Row r) -> r.open() == 0).thenComparing(r -> r.v().status())
                .thenComparing(r -> r.s().id()));
        Board.Totals t = board.totals();
        JsonWriter j = new JsonWriter().open('{').field("connected", connected).field("link", link)
                .field("at", now.toString());
        j.key("totals").open('{').field("flats", t.flats()).field("messages", t.messages()).field("badPayloads", t.bad())
                .field("duplicates", t.duplicates()).field("refusedFlats", t.refusedFlats())
                .field("unknownFlats", t.unknownFlats()).field("unsigned", t.unsigned()).close('}');
        j.key("flats").open('[');
        for (Row r : rows) {
            flat(j, r.s(), r.v(), rules, now);
        }
        return j.close(']').close('}').toString();
    }

    private static void flat(JsonWriter j, Snapshot s, Verdict v, Rules rules, Instant now) {
        j.open('{').field("flat", s.id()).field("status", v.status().name()).field("explanation", v.explanation());
        if (s.occupancy() != null) {
            j.field("occupancy", s.occupancy().state()).field("occupancyExplanation", s.occupancy().explanation());
        } else {
            j.field("occupancy", "UNKNOWN").field("occupancyExplanation", "the flat has not told its occupancy yet");
        }
        j.field("summary", s.summary() == null ? "" : s.summary().text());
        j.key("alerts").open('[');
        for (Entry e : s.alerts()) {
            AlertMessage a = e.alert();
            j.open('{').field("id", a.id()).field("kind", a.kind()).field("kindWords", BoardTime.kind(a.kind()))
                    .field("state", a.state()).field("title", a.title())
                    .field("room", a.room()).field("raisedAt", a.raisedAt() == null ? null : a.raisedAt().toString())
                    .field("seq", a.seq()).field("explanation", alertWords(s.id(), e, rules, now)).close('}');
        }
        j.close(']');
        Map<String, Health> devices = new TreeMap<>(s.devices());
        j.key("offlineSensors").open('[');
        devices.forEach((uid, h) -> {
            if (!h.status().equals("ONLINE")) {
                j.open('{').field("uid", uid).field("status", h.status()).field("explanation", h.explanation().isEmpty()
                        ? "sensor " + uid + " is " + h.status() : h.explanation()).close('}');
            }
        });
        j.close(']').key("lowBatteries").open('[');
        devices.forEach((uid, h) -> {
            boolean lowPercent = h.battery() != null && h.battery() <= rules.lowBatteryPercent();
            if (lowPercent || h.batteryLow()) {
                String words = lowPercent ? "battery of " + uid + " at " + h.battery() + " % (low at "
                        + rules.lowBatteryPercent() + " % or less)" : "battery of " + uid + " low, its node says"
                        + (h.millivolts() == null ? "" : String.format(java.util.Locale.ROOT, " (%.2f V)", h.millivolts() / 1000.0));
                j.open('{').field("uid", uid).field("battery", h.battery()).field("explanation", words).close('}');
            }
        });
        j.close(']').field("badPayloads", s.bad()).field("lastBadPayload", s.lastBad())
                .field("duplicates", s.duplicates()).field("dropped", s.dropped()).close('}');
    }

    /** @return e.g. "Fall? in Bedroom, raised at 14:02: … — acknowledgement sent by Eva at 14:05, waiting for the flat" */
    static String alertWords(String flat, Entry e, Rules rules, Instant now) {
        AlertMessage a = e.alert();
        StringBuilder b = new StringBuilder("Flat ").append(flat).append(": ").append(a.title().isEmpty() ? BoardTime.kind(a.kind()) : a.title());
        if (!a.room().isEmpty()) {
            b.append(" in ").append(a.room());
        }
        b.append(", raised at ").append(BoardTime.time(a.raisedAt(), now, rules.zone()));
        if (!a.text().isEmpty()) {
            b.append(": ").append(a.text());
        }
        switch (a.state()) {
            case "OPEN" -> b.append(e.ackSentAt() == null ? " — not acknowledged yet"
                    : " — acknowledgement sent by " + e.ackSentBy() + " at " + BoardTime.time(e.ackSentAt(), now, rules.zone())
                    + ", waiting for the flat to confirm it");
            case "ACKNOWLEDGED" -> b.append(" — acknowledged by ").append(a.acknowledgedBy().isEmpty() ? "someone" : a.acknowledgedBy())
                    .append(" at ").append(BoardTime.time(a.acknowledgedAt(), now, rules.zone()))
                    .append(e.confirmedAt() == null ? "" : "; the flat confirmed it at " + BoardTime.time(e.confirmedAt(), now, rules.zone()));
            default -> b.append(" — cleared at the flat (its cause ended or it was dealt with)");
        }
        return b.toString();
    }
}
