package org.tinysep.api.log;

import java.time.Instant;
import java.util.Set;

/**
 * What to look for in a log's history (thesis 3.8: the logs keep a history the user can search).
 *
 * @param from    the earliest entry time included, or null for no lower bound
 * @param to      the latest entry time included, or null for no upper bound
 * @param origins the origins wanted (empty: any). An entry matches when its origin equals one of them or begins
 *                with one of them followed by a space (packet origins such as {@code node 1.17 via 127.0.0.1:4000}
 *                match {@code node 1.17})
 * @param kinds   the kinds wanted, by name (empty: any). Event log: {@link EventKind} names. Packet log:
 *                {@link Direction} names, plus {@code REJECTED} (a note is present) and {@code GOOD} (no note)
 * @param limit   at most this many entries are returned: the newest matching ones
 */
public record LogQuery(Instant from, Instant to, Set<String> origins, Set<String> kinds, int limit) {

    /** Kind name matching a packet entry with a note (a rejected packet or a failed send). */
    public static final String REJECTED = "REJECTED";
    /** Kind name matching a packet entry without a note. */
    public static final String GOOD = "GOOD";

    public LogQuery {
        origins = origins == null ? Set.of() : Set.copyOf(origins);
        kinds = kinds == null ? Set.of() : Set.copyOf(kinds);
        if (limit < 1) {
            throw new IllegalArgumentException("limit must be at least 1, not " + limit);
        }
        if (from != null && to != null && from.isAfter(to)) {
            throw new IllegalArgumentException("from " + from + " is after to " + to);
        }
    }

    /** @return a query for the newest {@code limit} entries of any time, origin and kind */
    public static LogQuery newest(int limit) {
        return new LogQuery(null, null, Set.of(), Set.of(), limit);
    }

    /** @return whether {@code time} lies within {@link #from()} .. {@link #to()} */
    public boolean covers(Instant time) {
        return (from == null || !time.isBefore(from)) && (to == null || !time.isAfter(to));
    }

    /** @return whether {@code origin} is one of {@link #origins()} (or begins with one and a space) */
    public boolean matchesOrigin(String origin) {
        if (origins.isEmpty()) {
            return true;
        }
        for (String o : origins) {
            if (origin.equals(o) || origin.startsWith(o + " ")) {
                return true;
            }
        }
        return false;
    }

    /** @return whether an event entry matches every part of this query */
    public boolean matches(EventEntry e) {
        return covers(e.time()) && matchesOrigin(e.origin()) && (kinds.isEmpty() || kinds.contains(e.kind().name()));
    }

    /** @return whether a packet entry matches every part of this query */
    public boolean matches(PacketEntry p) {
        if (!covers(p.time()) || !matchesOrigin(p.origin())) {
            return false;
        }
        return kinds.isEmpty() || kinds.contains(p.direction().name())
                || kinds.contains(p.note().isEmpty() ? GOOD : REJECTED);
    }
}
