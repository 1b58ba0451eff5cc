package org.tinysep.api.bus;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives the payloads of one AmICA node (thesis A.1). */
@ConsumerType
public interface BusRadioAmicaListener {

    /**
     * @param source  the bus device the payload came through
     * @param payload the payload bytes (a copy owned by this listener)
     * @param at      when the packet was received
     */
    void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at);
}
