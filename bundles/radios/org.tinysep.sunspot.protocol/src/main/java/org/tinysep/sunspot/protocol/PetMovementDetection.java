package org.tinysep.sunspot.protocol;

/**
 * Pet Movement Detection payload {@code 5 1 0 A} (thesis Table 3.2): A = 1 a pet motion was detected, A = 0 none.
 * Sent by the pet collar node.
 *
 * @param detected true if the pet moved
 */
public record PetMovementDetection(boolean detected) implements SunSpotPayload {

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.PET_COLLAR;
    }
}
