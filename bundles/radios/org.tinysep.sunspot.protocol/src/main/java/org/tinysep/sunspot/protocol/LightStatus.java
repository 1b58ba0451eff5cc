package org.tinysep.sunspot.protocol;

/**
 * Light Status payload {@code 4 1 0 A} (thesis Table 3.2): A = light brightness in percent, 0..100. Sent by the light
 * sensor node, which has no actuator.
 *
 * @param percent the brightness, 0..100
 */
public record LightStatus(int percent) implements SunSpotPayload {

    /** @throws IllegalArgumentException if percent is outside 0..100 */
    public LightStatus {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException("percent " + percent + " is outside 0..100");
        }
    }

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.LIGHT;
    }
}
