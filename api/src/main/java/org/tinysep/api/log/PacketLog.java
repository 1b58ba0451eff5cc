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
}
