package org.tinysep.flatoccupancy.internal;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.tinysep.api.service.Occupancy;

/**
 * Flat Occupancy's decision in the system backup (docs/backup.md), so a restart resumes from it instead of
 * UNKNOWN. State keys: {@code occupancy} (OCCUPIED/UNOCCUPIED/UNKNOWN), {@code since}, and while a leave check is
 * pending {@code lastClose} and {@code leaveDeadline} (ISO instants).
 */
final class SavedOccupancy {

    private SavedOccupancy() {
    }

    static Map<String, String> toState(OccupancyLogic.Saved s) {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("occupancy", s.state().name());
        m.put("since", s.since().toString());
        if (s.lastClose() != null) {
            m.put("lastClose", s.lastClose().toString());
        }
        if (s.leaveDeadline() != null) {
            m.put("leaveDeadline", s.leaveDeadline().toString());
        }
        return m;
    }

    /**
     * @return the saved decision; null when the backup holds none (an older backup) or it cannot be read, which
     *         is named in {@code problems}
     */
    static OccupancyLogic.Saved fromState(Map<String, String> state, List<String> problems) {
        String o = state.get("occupancy");
        if (o == null) {
            return null;
        }
        try {
            return new OccupancyLogic.Saved(Occupancy.valueOf(o.strip().toUpperCase(Locale.ROOT)),
                    Instant.parse(state.get("since")), instant(state.get("lastClose")),
                    instant(state.get("leaveDeadline")));
        } catch (RuntimeException e) {
            problems.add("saved occupancy " + state + " cannot be read (" + e.getMessage() + "); starting UNKNOWN");
            return null;
        }
    }

    private static Instant instant(String v) {
        return v == null ? null : Instant.parse(v);
    }
}
