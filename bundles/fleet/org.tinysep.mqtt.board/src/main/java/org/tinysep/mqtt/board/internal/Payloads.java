package org.tinysep.mqtt.board.internal;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.Map;
import java.util.Set;
import org.tinysep.json.JsonReader;

/**
 * Turns the contract's payloads into records. A payload that breaks the contract throws
 * {@link IllegalArgumentException} whose message says what is wrong in plain words: the board counts it and shows
 * the reason, it never stops for it. Texts are cut to {@link #MAX_TEXT} characters (bounded memory per flat).
 */
final class Payloads {

    static final int MAX_TEXT = 400;
    static final int MAX_PAYLOAD = 16 * 1024;
    static final Set<String> ALERT_STATES = Set.of("OPEN", "ACKNOWLEDGED", "CLEARED");
    static final Set<String> OCCUPANCY = Set.of("OCCUPIED", "UNOCCUPIED", "UNKNOWN");

    record Platform(String version, Instant startedAt, Instant heartbeatAt, int heartbeatSeconds) { }

    record Summary(Instant at, String text) { }

    record Occupancy(String state, Instant since, String explanation) { }

    /** A device's health; the bridge sends {@code batteryLow} (and millivolts) where the node reports no percentage. */
    record Health(String status, Integer battery, boolean batteryLow, Integer millivolts, Instant lastReport,
            String explanation) { }

    record AlertMessage(String id, String kind, String state, Instant raisedAt, String room, String title,
            String text, String acknowledgedBy, Instant acknowledgedAt, long seq) { }

    private Payloads() {
    }

    static String text(byte[] payload) {
        if (payload.length > MAX_PAYLOAD) {
            throw new IllegalArgumentException("payload of " + payload.length + " bytes, more than " + MAX_PAYLOAD);
        }
        return new String(payload, StandardCharsets.UTF_8);
    }

    /**
     * @return the members of the flat JSON object a payload holds, every value as text (null as absent)
     * @throws IllegalArgumentException "not a flat JSON object: … at character N" (read strictly by the shared
     *         {@link JsonReader})
     */
    static Map<String, String> fields(String text) {
        return JsonReader.flatObject(text, MAX_PAYLOAD);
    }

    static String status(String text) {
        String s = text.trim();
        if (!s.equals("online") && !s.equals("offline")) {
            throw new IllegalArgumentException("status must be online or offline, not '" + cut(s, 40) + "'");
        }
        return s;
    }

    static Platform platform(Map<String, String> m) {
        int seconds = integer(m, "heartbeatSeconds");
        if (seconds <= 0) {
            throw new IllegalArgumentException("heartbeatSeconds must be positive, not " + seconds);
        }
        return new Platform(optional(m, "version"), instantOrNull(m, "startedAt"), instant(m, "heartbeatAt"), seconds);
    }

    static Summary summary(Map<String, String> m) {
        return new Summary(instant(m, "at"), required(m, "text"));
    }

    static Occupancy occupancy(Map<String, String> m) {
        String state = required(m, "state");
        if (!OCCUPANCY.contains(state)) {
            throw new IllegalArgumentException("occupancy state must be one of " + OCCUPANCY + ", not '" + cut(state, 40) + "'");
        }
        return new Occupancy(state, instantOrNull(m, "since"), optional(m, "explanation"));
    }

    static Health health(Map<String, String> m) {
        String battery = m.get("battery");
        Integer percent = null;
        if (battery != null) {
            try {
                percent = (int) Math.round(Double.parseDouble(battery));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("battery must be a number or null, not '" + cut(battery, 40) + "'");
            }
        }
        Integer millivolts = null;
        if (m.get("batteryMillivolts") != null) {
            try {
                millivolts = (int) Math.round(Double.parseDouble(m.get("batteryMillivolts")));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("batteryMillivolts must be a number or null");
            }
        }
        return new Health(required(m, "status"), percent, "true".equals(m.get("batteryLow")), millivolts,
                instantOrNull(m, "lastReport"), optional(m, "explanation"));
    }

    static AlertMessage alert(String flat, String topicId, Map<String, String> m) {
        String id = m.getOrDefault("id", topicId);
        if (!id.equals(topicId)) {
            throw new IllegalArgumentException("alert id " + cut(id, 40) + " does not match its topic's " + topicId);
        }
        String from = m.get("flat");
        if (from != null && !from.equals(flat)) {
            throw new IllegalArgumentException("alert says flat " + cut(from, 40) + " on flat " + flat + "'s topic");
        }
        String state = required(m, "state");
        if (!ALERT_STATES.contains(state)) {
            throw new IllegalArgumentException("alert state must be one of " + ALERT_STATES + ", not '" + cut(state, 40) + "'");
        }
        long seq;
        try {
            seq = Long.parseLong(required(m, "seq"));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("alert seq must be a whole number");
        }
        return new AlertMessage(id, optional(m, "kind"), state, instantOrNull(m, "raisedAt"), optional(m, "room"),
                optional(m, "title"), optional(m, "text"), optional(m, "acknowledgedBy"),
                instantOrNull(m, "acknowledgedAt"), seq);
    }

    static String cut(String s, int max) {
        return s == null || s.length() <= max ? s : s.substring(0, max - 1) + "…";
    }

    private static String required(Map<String, String> m, String key) {
        String v = m.get(key);
        if (v == null || v.isBlank()) {
            throw new IllegalArgumentException("'" + key + "' is missing");
        }
        return cut(v, MAX_TEXT);
    }

    private static String optional(Map<String, String> m, String key) {
        String v = m.get(key);
        return v == null ? "" : cut(v, MAX_TEXT);
    }

    private static int integer(Map<String, String> m, String key) {
        try {
            return Integer.parseInt(required(m, key));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + key + "' must be a whole number");
        }
    }

    private static Instant instant(Map<String, String> m, String key) {
        Instant i = instantOrNull(m, key);
        if (i == null) {
            throw new IllegalArgumentException("'" + key + "' is missing");
        }
        return i;
    }

    private static Instant instantOrNull(Map<String, String> m, String key) {
        String v = m.get(key);
        if (v == null || v.isBlank()) {
            return null;
        }
        try {
            return Instant.parse(v);
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("'" + key + "' is not an ISO-8601 time: '" + cut(v, 40) + "'");
        }
    }
}
