package org.tinysep.sunspot.protocol;

/**
 * Temperature Status payload {@code 3 1 A B} (thesis Table 3.2): A and B form a signed 16-bit big-endian number of
 * tenths of a degree Celsius, e.g. 21.5 °C = {@code 0x00D7} = 215. The value must lie in the Sun SPOT temperature
 * sensor's range, {@value #MIN_CELSIUS} .. {@value #MAX_CELSIUS} °C. The encoder rounds to the nearest tenth.
 *
 * @param celsius the temperature in degrees Celsius, {@value #MIN_CELSIUS} .. {@value #MAX_CELSIUS}
 */
public record TemperatureStatus(double celsius) implements SunSpotPayload {

    /** Lowest temperature the Sun SPOT sensor reports, °C. */
    public static final double MIN_CELSIUS = -40.0;
    /** Highest temperature the Sun SPOT sensor reports, °C. */
    public static final double MAX_CELSIUS = 125.0;

    /** @throws IllegalArgumentException if celsius is NaN or outside the sensor's range */
    public TemperatureStatus {
        if (!(celsius >= MIN_CELSIUS && celsius <= MAX_CELSIUS)) {
            throw new IllegalArgumentException("temperature " + celsius + " °C is outside -40.0..125.0");
        }
    }

    /**
     * @param tenths tenths of a degree Celsius, -400..1250
     * @return the status
     * @throws IllegalArgumentException if out of range
     */
    public static TemperatureStatus ofTenths(int tenths) {
        return new TemperatureStatus(tenths / 10.0);
    }

    /** @return the temperature in tenths of a degree, rounded to the nearest, as it travels in the payload */
    public int tenths() {
        return (int) Math.round(celsius * 10);
    }

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.TEMPERATURE;
    }
}
