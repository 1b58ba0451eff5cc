package org.tinysep.api.log;

import java.util.List;
import org.osgi.annotation.versioning.ProviderType;

/**
 * The platform's event log, provided by the device manager. Recording never blocks for long and never throws
 * for ordinary input. Creation, removal and connection entries for services are recorded by the device manager
 * itself; devices record what they observe ({@link EventKind#DEVICE_EVENT}) and their trouble.
 */
@ProviderType
public interface EventLog {

    /** Appends an entry stamped with the platform's current time. */
    void record(EventKind kind, String origin, String message);

    /** @return the newest {@code max} entries, oldest first */
    List<EventEntry> recent(int max);

    /**
     * Searches the log's history: the stored history where the log keeps one, else what it holds in memory.
     * The default searches {@link #recent(int)}.
     *
     * @since 1.1
     */
    default LogHistory<EventEntry> query(LogQuery query) {
        List<EventEntry> all = recent(Integer.MAX_VALUE).stream().filter(query::matches).toList();
        return new LogHistory<>(all.subList(Math.max(0, all.size() - query.limit()), all.size()), all.size(), 0);
    }
}
