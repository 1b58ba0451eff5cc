package org.tinysep.sunspot.temperature.internal;

import java.time.Instant;
import java.util.List;
import java.util.OptionalDouble;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.TemperatureListener;
import org.tinysep.api.sensor.TemperatureProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.SensorDevice;
import org.tinysep.device.support.sensor.Source;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * Abstracts one Sun SPOT temperature sensor: Temperature Status payloads become temperatures in degrees Celsius.
 * {@link #celsius()} is always the latest reading; listeners hear a reading only when it differs from the last one
 * they heard by at least the dead band (parameter {@code deadbandCelsius}), so sensor noise does not reach them.
 */
final class SunSpotTemperatureDevice extends SensorDevice<TemperatureListener, Double> implements TemperatureProvider {

    static final double DEFAULT_DEADBAND = 0.1;
    /** Absorbs binary rounding, so that 21.6 → 21.7 counts as a step of 0.1. */
    private static final double EPSILON = 1e-9;
    private static final Source.Frames FRAMES =
            new Source.Frames(SunSpotSensorType.TEMPERATURE.code(), "temperature");

    private volatile double deadband = DEFAULT_DEADBAND;

    SunSpotTemperatureDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Source.sunSpot(bus, FRAMES, SunSpotPayloads::decode, TemperatureStatus.class,
                (t, at) -> t.celsius()), NodeType.TEMPERATURE, "Temperature sensor " + bus.nodeAddress(),
                TemperatureProvider.class);
    }

    /** A change is a step of at least the dead band from the last reading the listeners heard. */
    @Override
    protected boolean isChange(Double announced, Double celsius) {
        return Math.abs(celsius - announced) >= deadband - EPSILON;
    }

    @Override
    protected void tell(TemperatureListener listener, Double celsius, boolean first, Instant at) {
        listener.temperatureChanged(this, celsius, at);
    }

    @Override
    public OptionalDouble celsius() {
        Double c = latest();
        return c == null ? OptionalDouble.empty() : OptionalDouble.of(c);
    }

    double deadband() {
        return deadband;
    }

    @Override
    protected List<Parameter> settings() {
        return List.of(Parameter.writable("deadbandCelsius", deadband,
                "listeners hear a reading only if it differs from the last they heard by at least this"));
    }

    @Override
    protected List<Parameter> readings() {
        return List.of(Parameter.readOnly("celsius", latest(), "latest reading in degrees Celsius"),
                Parameter.readOnly("lastUpdate", lastUpdate(), "when the latest reading arrived"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"deadbandCelsius".equals(key)) {
            throw unknownParameter(key);
        }
        double d;
        try {
            d = Double.parseDouble(value.strip());
        } catch (NumberFormatException | NullPointerException e) {
            d = Double.NaN;
        }
        if (!Double.isFinite(d) || d < 0) {
            throw new IllegalArgumentException("deadbandCelsius must be a number >= 0, was '" + value + "'");
        }
        deadband = d;
        event("dead band set to " + d + " °C");
    }
}
