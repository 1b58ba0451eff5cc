package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.TreeMap;

/**
 * The last activity per room and the last activity overall, kept in the system backup (docs/backup.md) so a
 * restart does not forget when each room was last used. State keys: {@code room.<room uid>} = ISO instant, and
 * {@code last.at}, {@code last.room}, {@code last.roomName}, {@code last.description}, {@code last.limitSeconds}.
 * Thread-safe.
 */
final class RoomActivity {

    private final Map<String, Instant> perRoom = new TreeMap<>();

    synchronized void seen(Activity a) {
        if (!a.roomUid().isEmpty()) {
            perRoom.merge(a.roomUid(), a.at(), (old, now) -> now.isAfter(old) ? now : old);
        }
    }

    synchronized String describe() {
        return perRoom.isEmpty() ? "" : perRoom.toString();
    }

    synchronized Map<String, String> state(Activity last) {
        Map<String, String> m = new LinkedHashMap<>();
        perRoom.forEach((room, at) -> m.put("room." + room, at.toString()));
        if (last != null) {
            m.put("last.at", last.at().toString());
            m.put("last.room", last.roomUid());
            m.put("last.roomName", last.roomName());
            m.put("last.description", last.description());
            m.put("last.limitSeconds", Long.toString(last.limit().toSeconds()));
        }
        return m;
    }

    /** Takes the per-room times back; @return the saved last activity, or null when there is none */
    synchronized Activity restore(Map<String, String> state) {
        state.forEach((k, v) -> {
            if (k.startsWith("room.")) {
                perRoom.put(k.substring(5), Instant.parse(v));
            }
        });
        if (!state.containsKey("last.at")) {
            return null;
        }
        return new Activity(state.getOrDefault("last.room", ""), state.getOrDefault("last.roomName", ""),
                state.getOrDefault("last.description", "") + " (before restart)", Instant.parse(state.get("last.at")),
                Duration.ofSeconds(Long.parseLong(state.get("last.limitSeconds"))));
    }
}
