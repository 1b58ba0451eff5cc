package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The last activity per room and the last activity overall, kept in the system backup (docs/backup.md) so a
 * restart does not forget when each room was last used, nor the quiet time that was being counted. State keys:
 * {@code room.<room uid>} = ISO instant, {@code last.at}, {@code last.room}, {@code last.roomName},
 * {@code last.description}, {@code last.limitSeconds}, {@code last.explanation} (why that limit),
 * {@code watching.from} (since when the flat was watched), {@code alert.handedOver} (when the alert last handed to the Mail Manager was due). Thread-safe.
 */
final class RoomActivity {

    /** What a backup held. Every field may be null. */
    record Saved(Activity last, Instant watchedFrom, Instant handedOverDue) {
    }

    private final Map<String, Instant> perRoom = new TreeMap<>();

    /** Records the room's newest activity; one from a clock that went back replaces a time in the future. */
    synchronized void seen(Activity a) {
        if (!a.roomUid().isEmpty()) {
            perRoom.merge(a.roomUid(), a.at(), (old, now) -> now.isAfter(old)
                    || InactivityLogic.ahead(old, now) ? now : old);
        }
    }

    synchronized String describe() {
        return perRoom.isEmpty() ? "" : perRoom.toString();
    }

    synchronized Map<String, String> state(Activity last, Instant watchedFrom, Instant handedOverDue) {
        Map<String, String> m = new LinkedHashMap<>();
        perRoom.forEach((room, at) -> m.put("room." + room, at.toString()));
        if (last != null) {
            m.put("last.at", last.at().toString());
            m.put("last.room", last.roomUid());
            m.put("last.roomName", last.roomName());
            m.put("last.description", last.description());
            m.put("last.limitSeconds", Long.toString(last.limit().toSeconds()));
            if (!last.explanation().isEmpty()) {
                m.put("last.explanation", last.explanation());
            }
        }
        if (watchedFrom != null) {
            m.put("watching.from", watchedFrom.toString());
        }
        if (handedOverDue != null) {
            m.put("alert.handedOver", handedOverDue.toString());
        }
        return m;
    }

    /**
     * Takes the saved state back. The per-room times are a record of what was seen and come back as saved, virtual
     * times included (a room's next activity replaces a time from the future, see {@link #seen}); the caller
     * re-bases the last activity and the watching start, which decide. An entry that cannot be read is skipped and
     * named in {@code problems}.
     */
    synchronized Saved restore(Map<String, String> state, List<String> problems) {
        state.forEach((k, v) -> {
            if (k.startsWith("room.")) {
                Instant at = instant(k, v, problems);
                if (at != null) {
                    perRoom.put(k.substring(5), at);
                }
            }
        });
        Activity last = null;
        Instant at = instant("last.at", state.get("last.at"), problems);
        if (at != null) {
            try {
                String description = state.getOrDefault("last.description", "activity");
                last = new Activity(state.getOrDefault("last.room", ""), state.getOrDefault("last.roomName", ""),
                        description.endsWith(" (before restart)") ? description : description + " (before restart)",
                        at, Duration.ofSeconds(Long.parseLong(state.getOrDefault("last.limitSeconds", ""))),
                        state.getOrDefault("last.explanation", ""));
            } catch (IllegalArgumentException e) {
                problems.add("saved last activity not restored: " + e.getMessage());
            }
        }
        return new Saved(last, instant("watching.from", state.get("watching.from"), problems),
                instant("alert.handedOver", state.get("alert.handedOver"), problems));
    }

    private static Instant instant(String key, String value, List<String> problems) {
        if (value == null) {
            return null;
        }
        try {
            return Instant.parse(value);
        } catch (RuntimeException e) {
            problems.add("saved " + key + "=" + value + " is not a time; ignored");
            return null;
        }
    }
}
