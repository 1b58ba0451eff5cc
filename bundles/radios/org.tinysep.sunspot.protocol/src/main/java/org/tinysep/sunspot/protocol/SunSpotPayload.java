package org.tinysep.sunspot.protocol;

/**
 * A payload of thesis Table 3.2 (plus TinySEP's Movement Detection version 2 and the person node's reports), decoded. {@link SunSpotPayloads}
 * converts between these records and bytes. Sun SPOT payloads only travel from the node to the platform: the thesis
 * defines no commands.
 */
public sealed interface SunSpotPayload
        permits MovementDetection, TemperatureStatus, LightStatus, PetMovementDetection, ButtonReport,
        MovementSummaryReport, BurstChunk {

    /** @return the sensor type this payload belongs to; its code is the payload's first byte */
    SunSpotSensorType sensorType();
}
