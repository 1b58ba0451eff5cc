package org.tinysep.api.bus;

import java.time.Instant;
import org.osgi.annotation.versioning.ConsumerType;

/** Receives the payloads of one Sun SPOT node (thesis A.2). */
@ConsumerType
public interface BusRadioSunSpotListener {

    /**
     * @param source     the bus device the payload came through
     * @param sensorType the sensor type byte of the packet header
     * @param payload    the payload bytes (a copy owned by this listener)
     * @param at         when the packet was received
     */
    void payloadReceived(BusRadioSunSpotProvider source, int sensorType, byte[] payload, Instant at);
}
