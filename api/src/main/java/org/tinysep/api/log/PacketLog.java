package org.tinysep.api.log;

import java.util.List;
import org.osgi.annotation.versioning.ProviderType;

/** The platform's packet log, provided by the device manager; bus radios record every packet here. */
@ProviderType
public interface PacketLog {

    /**
     * Records one packet, stamped with the platform's current time.
     *
     * @param note empty for a good packet, otherwise why it was rejected
     */
    void record(Direction direction, String origin, byte[] bytes, String note);

    /** @return the newest {@code max} entries, oldest first */
    List<PacketEntry> recent(int max);

    /**
     * Searches the log's history: the stored history where the log keeps one, else what it holds in memory.
     * The default searches {@link #recent(int)}.
     *
     * @since 1.1
     */
    default LogHistory<PacketEntry> query(LogQuery query) {
        List<PacketEntry> all = recent(Integer.MAX_VALUE).stream().filter(query::matches).toList();
        return new LogHistory<>(all.subList(Math.max(0, all.size() - query.limit()), all.size()), all.size(), 0);
    }
}
