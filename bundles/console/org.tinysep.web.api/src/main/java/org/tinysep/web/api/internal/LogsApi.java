package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;
import org.tinysep.web.api.internal.PlatformView.DeviceRef;

/**
 * {@code /api/events} and {@code /api/packets}: searches of the logs' history through {@link LogQuery}
 * (parameters {@code from}, {@code to} as ISO-8601 instants, {@code origin} = a device or driver UID or name,
 * repeated or comma-separated, {@code kind} likewise, {@code limit} 1..{@value #MAX_LIMIT}, default {@value #DEFAULT_LIMIT}).
 */
public final class LogsApi {

    static final int DEFAULT_LIMIT = 200;
    static final int MAX_LIMIT = 5000;

    private final PlatformView platform;
    private final PacketDescriptions descriptions;

    LogsApi(PlatformView platform, PacketDescriptions descriptions) {
        this.platform = platform;
        this.descriptions = descriptions;
    }

    public Map<String, Object> events(EventLog log, Map<String, String[]> params) {
        LogQuery q = query(params, true);
        LogHistory<EventEntry> h = log.query(q);
        Map<String, String> names = platform.names();
        List<Object> entries = new ArrayList<>();
        h.entries().forEach(e -> entries.add(event(e, names)));
        return answer(entries, h);
    }

    public Map<String, Object> packets(PacketLog log, Map<String, String[]> params) {
        LogQuery q = query(params, false);
        LogHistory<PacketEntry> h = log.query(q);
        List<Object> entries = new ArrayList<>();
        h.entries().forEach(p -> entries.add(packet(p, descriptions)));
        return answer(entries, h);
    }

    static Map<String, Object> event(EventEntry e, Map<String, String> names) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("seq", e.sequence());
        m.put("time", e.time());
        m.put("kind", e.kind());
        m.put("origin", e.origin());
        m.put("originName", names.getOrDefault(e.origin(), e.origin()));
        m.put("message", e.message());
        return m;
    }

    static Map<String, Object> packet(PacketEntry p, PacketDescriptions descriptions) {
        byte[] bytes = p.bytes();
        PacketDescriptions.Description d = descriptions.describe(p.origin(), bytes);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("seq", p.sequence());
        m.put("time", p.time());
        m.put("direction", p.direction());
        m.put("origin", p.origin());
        m.put("hex", HexFormat.ofDelimiter(" ").formatHex(bytes));
        m.put("decimal", p.decimal());
        m.put("note", p.note());
        m.put("decoded", d.decoded());
        m.put("undecoded", d.undecoded());
        m.put("node", node(p.origin()));
        return m;
    }

    /** @return the node address an origin such as {@code node 1.17 via udp …} names, else empty */
    static String node(String origin) {
        if (!origin.startsWith("node ")) {
            return "";
        }
        int end = origin.indexOf(' ', 5);
        return end < 0 ? origin.substring(5) : origin.substring(5, end);
    }

    private static Map<String, Object> answer(List<Object> entries, LogHistory<?> h) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("entries", entries);
        m.put("matched", h.matched());
        m.put("damagedLines", h.damagedLines());
        return m;
    }

    private LogQuery query(Map<String, String[]> params, boolean events) {
        Instant from = instant(params, "from");
        Instant to = instant(params, "to");
        int limit = DEFAULT_LIMIT;
        String l = first(params, "limit");
        if (l != null) {
            try {
                limit = Integer.parseInt(l.strip());
            } catch (NumberFormatException e) {
                throw ApiException.badRequest("limit must be a whole number, not '" + l + "'");
            }
            if (limit < 1 || limit > MAX_LIMIT) {
                throw ApiException.badRequest("limit must be between 1 and " + MAX_LIMIT);
            }
        }
        Set<String> kinds = new LinkedHashSet<>();
        for (String k : all(params, "kind")) {
            String kind = k.toUpperCase(Locale.ROOT);
            if (events && Arrays.stream(EventKind.values()).noneMatch(v -> v.name().equals(kind))) {
                throw ApiException.badRequest("unknown kind '" + k + "': one of " + Arrays.toString(EventKind.values()));
            }
            if (!events && !Set.of("RECEIVED", "SENT", LogQuery.REJECTED, LogQuery.GOOD).contains(kind)) {
                throw ApiException.badRequest("unknown kind '" + k + "': RECEIVED, SENT, REJECTED or GOOD");
            }
            kinds.add(kind);
        }
        Set<String> origins = new LinkedHashSet<>();
        for (String o : all(params, "origin")) {
            origins.addAll(origins(o));
        }
        try {
            return new LogQuery(from, to, origins, kinds, limit);
        } catch (IllegalArgumentException e) {
            throw ApiException.badRequest(e.getMessage());
        }
    }

    /** A device or driver given by UID or name: its UID, and {@code node <address>} for a device with a node. */
    private Set<String> origins(String ref) {
        Set<String> out = new LinkedHashSet<>();
        out.add(ref);
        for (DeviceRef d : platform.devices()) {
            if (d.uid().equals(ref) || Safely.get(() -> d.device().name(), "").equalsIgnoreCase(ref)) {
                out.add(d.uid());
                if (!d.nodeAddress().isEmpty()) {
                    out.add("node " + d.nodeAddress());
                }
            }
        }
        platform.drivers().stream().filter(d -> Safely.get(d::name, "").equalsIgnoreCase(ref))
                .forEach(d -> out.add(Safely.get(d::uid, ref)));
        return out;
    }

    private static Instant instant(Map<String, String[]> params, String key) {
        String v = first(params, key);
        if (v == null || v.isBlank()) {
            return null;
        }
        try {
            return Instant.parse(v.strip());
        } catch (DateTimeParseException e) {
            throw ApiException.badRequest(key + " must be an ISO-8601 instant such as 2026-11-25T14:00:00Z, not '" + v + "'");
        }
    }

    private static String first(Map<String, String[]> params, String key) {
        String[] v = params.get(key);
        return v == null || v.length == 0 ? null : v[0];
    }

    private static List<String> all(Map<String, String[]> params, String key) {
        List<String> out = new ArrayList<>();
        for (String v : params.getOrDefault(key, new String[0])) {
            for (String part : v.split(",")) {
                if (!part.isBlank()) {
                    out.add(part.strip());
                }
            }
        }
        return out;
    }
}
