package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.tinysep.api.service.Room;

/**
 * Inactivity limits per room: a per-room override (by room UID, then room name, then room type) beats the
 * default of the room's type, which beats the general default. Entries are written {@code key=minutes}, separated
 * by commas; names and types compare without regard to case.
 */
final class LimitTable {

    private final Duration defaultLimit;
    private final Map<String, Duration> typeDefaults;
    private final Map<String, Duration> overrides;
    private final List<String> problems;

    private LimitTable(Duration defaultLimit, Map<String, Duration> typeDefaults, Map<String, Duration> overrides,
            List<String> problems) {
        this.defaultLimit = defaultLimit;
        this.typeDefaults = typeDefaults;
        this.overrides = overrides;
        this.problems = problems;
    }

    /**
     * Parses the configuration. Bad entries are skipped and reported by {@link #problems()}; they never stop the
     * service.
     */
    static LimitTable parse(int defaultMinutes, String typeLimits, String roomLimits) {
        List<String> problems = new ArrayList<>();
        Duration fallback = Duration.ofMinutes(120);
        if (defaultMinutes < 1) {
            problems.add("defaultLimitMinutes must be at least 1, was " + defaultMinutes + "; using 120");
        } else {
            fallback = Duration.ofMinutes(defaultMinutes);
        }
        return new LimitTable(fallback, entries("typeLimits", typeLimits, problems),
                entries("roomLimits", roomLimits, problems), Collections.unmodifiableList(problems));
    }

    private static Map<String, Duration> entries(String key, String text, List<String> problems) {
        Map<String, Duration> out = new LinkedHashMap<>();
        if (text == null || text.isBlank()) {
            return out;
        }
        for (String entry : text.split(",")) {
            if (entry.isBlank()) {
                continue;
            }
            int eq = entry.lastIndexOf('=');
            String name = eq < 0 ? "" : entry.substring(0, eq).strip();
            String minutes = eq < 0 ? "" : entry.substring(eq + 1).strip();
            try {
                long m = Long.parseLong(minutes);
                if (name.isEmpty() || m < 1) {
                    throw new NumberFormatException();
                }
                out.put(name.toLowerCase(Locale.ROOT), Duration.ofMinutes(m));
            } catch (NumberFormatException e) {
                problems.add(key + ": ignored '" + entry.strip() + "' (write room=minutes, minutes at least 1)");
            }
        }
        return out;
    }

    /** @return the limit for a room the house plan knows */
    Duration limitFor(Room room) {
        for (String k : List.of(room.uid(), room.name(), room.type())) {
            Duration d = overrides.get(k.toLowerCase(Locale.ROOT));
            if (d != null) {
                return d;
            }
        }
        return typeDefaults.getOrDefault(room.type().toLowerCase(Locale.ROOT), defaultLimit);
    }

    /** @return the limit for a room UID the house plan does not know (an override by UID still applies) */
    Duration limitForUnknownRoom(String roomUid) {
        return overrides.getOrDefault(roomUid.toLowerCase(Locale.ROOT), defaultLimit);
    }

    Duration defaultLimit() {
        return defaultLimit;
    }

    /** @return one message per ignored configuration entry */
    List<String> problems() {
        return problems;
    }
}
