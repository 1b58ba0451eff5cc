package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.tinysep.inactivity.internal.person.Wearers;

/**
 * Each wearer's watch in the device's backup state (README "System backup and restarts"), beside the flat's keys:
 * {@code person.<n>.node} (the person node's UID), {@code .name}, {@code .heard}, {@code .lastMovement} (absent:
 * not moved since heard), {@code .worn}, {@code .room}, {@code .roomName} (where last seen); the activity that set
 * the wearer's limit {@code .seen.*} and the watch's last activity {@code .last.*} (each {@code at}, {@code room},
 * {@code roomName}, {@code description}, {@code limitSeconds}, {@code explanation}); {@code .watching.from};
 * {@code .alert.handedOver} (when the alert handed on was due) and {@code .alert.toService}. Pure.
 */
final class PersonBackup {

    static final String PREFIX = "person.";

    /** One wearer's watch as saved. {@code seen}, {@code last}, {@code watchingFrom}, {@code handedOver} may be null. */
    record SavedWatch(Wearers.Saved wearer, Activity seen, Activity last, Instant watchingFrom, Instant handedOver,
            boolean toService) {
    }

    private PersonBackup() {
    }

    static Map<String, String> write(List<SavedWatch> watches) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < watches.size(); i++) {
            SavedWatch s = watches.get(i);
            String p = PREFIX + i + ".";
            Wearers.Saved w = s.wearer();
            m.put(p + "node", w.nodeUid());
            m.put(p + "name", w.person());
            m.put(p + "heard", w.heard().toString());
            if (w.lastMovement() != null) {
                m.put(p + "lastMovement", w.lastMovement().toString());
            }
            m.put(p + "worn", Boolean.toString(w.worn()));
            m.put(p + "room", w.roomUid());
            m.put(p + "roomName", w.roomName());
            activity(m, p + "seen.", s.seen());
            activity(m, p + "last.", s.last());
            if (s.watchingFrom() != null) {
                m.put(p + "watching.from", s.watchingFrom().toString());
            }
            if (s.handedOver() != null) {
                m.put(p + "alert.handedOver", s.handedOver().toString());
                m.put(p + "alert.toService", Boolean.toString(s.toService()));
            }
        }
        return m;
    }

    private static void activity(Map<String, String> m, String p, Activity a) {
        if (a == null) {
            return;
        }
        m.put(p + "at", a.at().toString());
        m.put(p + "room", a.roomUid());
        m.put(p + "roomName", a.roomName());
        m.put(p + "description", a.description());
        m.put(p + "limitSeconds", Long.toString(a.limit().toSeconds()));
        m.put(p + "explanation", a.explanation());
    }

    /**
     * @return each saved wearer's watch; one that cannot be read is skipped and named in {@code problems} (the
     *         others come back)
     */
    static List<SavedWatch> read(Map<String, String> state, List<String> problems) {
        TreeSet<Integer> indexes = new TreeSet<>();
        state.keySet().stream().filter(k -> k.startsWith(PREFIX) && k.endsWith(".node")).forEach(k -> {
            try {
                indexes.add(Integer.parseInt(k.substring(PREFIX.length(), k.length() - ".node".length())));
            } catch (NumberFormatException e) {
                problems.add("saved " + k + " is not a wearer's entry; ignored");
            }
        });
        List<SavedWatch> out = new ArrayList<>();
        for (int i : indexes) {
            String p = PREFIX + i + ".";
            String node = state.get(p + "node");
            try {
                Wearers.Saved w = new Wearers.Saved(node, required(state, p + "name"),
                        Instant.parse(required(state, p + "heard")), instant(state, p + "lastMovement"),
                        !"false".equals(state.get(p + "worn")), state.get(p + "room"), state.get(p + "roomName"));
                out.add(new SavedWatch(w, activity(state, p + "seen."), activity(state, p + "last."),
                        instant(state, p + "watching.from"), instant(state, p + "alert.handedOver"),
                        "true".equals(state.get(p + "alert.toService"))));
            } catch (RuntimeException e) {
                problems.add("saved watch of " + node + " not restored (" + e.getMessage() + "): its wearer's "
                        + "watch begins again with the node's next summary");
            }
        }
        return out;
    }

    private static String required(Map<String, String> state, String key) {
        String v = state.get(key);
        if (v == null || v.isBlank()) {
            throw new IllegalArgumentException(key + " missing");
        }
        return v;
    }

    private static Instant instant(Map<String, String> state, String key) {
        String v = state.get(key);
        try {
            return v == null ? null : Instant.parse(v);
        } catch (RuntimeException e) {
            throw new IllegalArgumentException(key + "=" + v + " is not a time", e);
        }
    }

    private static Activity activity(Map<String, String> state, String p) {
        Instant at = instant(state, p + "at");
        if (at == null) {
            return null;
        }
        String description = state.getOrDefault(p + "description", "activity");
        try {
            return new Activity(state.getOrDefault(p + "room", ""), state.getOrDefault(p + "roomName", ""),
                    description, at, Duration.ofSeconds(Long.parseLong(state.getOrDefault(p + "limitSeconds", ""))),
                    state.getOrDefault(p + "explanation", ""));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(p + "limitSeconds: " + e.getMessage(), e);
        }
    }
}
