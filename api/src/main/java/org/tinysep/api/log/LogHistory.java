package org.tinysep.api.log;

import java.util.List;

/**
 * The answer to a {@link LogQuery}.
 *
 * @param entries      the newest matching entries, oldest first (at most the query's limit)
 * @param matched      how many entries matched in all (may exceed the number returned)
 * @param damagedLines how many stored lines could not be read and were skipped
 * @param <E>          {@link EventEntry} or {@link PacketEntry}
 */
public record LogHistory<E>(List<E> entries, long matched, long damagedLines) {

    public LogHistory {
        entries = List.copyOf(entries);
    }
}
