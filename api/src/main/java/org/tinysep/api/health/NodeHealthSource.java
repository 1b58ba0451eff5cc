package org.tinysep.api.health;

import org.osgi.annotation.versioning.ProviderType;

/**
 * Registered by every bus device beside its bus provider, with the same service properties (device UID, node
 * address, node types, room): the health of its node.
 */
@ProviderType
public interface NodeHealthSource {

    /** @return the node's health now; cheap, never blocks */
    NodeHealth health();

    /**
     * What {@link #health()} says now about {@link NodeHealth#online()} and {@link NodeHealth#batteryLow()}, without
     * building it: equal values mean equal flags. Lets a consumer that looks every second (Sensor Health) read
     * {@code health()} only when one of them changed; no allocation, never blocks.
     *
     * @return a value &ge; 0 that summarises the two flags, or -1 when this source cannot tell (read {@code health()})
     * @since 1.1
     */
    default int healthFlags() {
        return -1;
    }
}
