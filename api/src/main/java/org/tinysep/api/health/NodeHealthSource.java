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
}
