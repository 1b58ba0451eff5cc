package org.tinysep.sunspot.temperature.internal;

import java.time.Instant;
import java.util.List;
import java.util.OptionalDouble;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.TemperatureListener;
import org.tinysep.api.sensor.TemperatureProvider;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.SunSpotSensorType;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * Abstracts one Sun SPOT temperature sensor: Temperature Status payloads become temperatures in degrees Celsius.
 * {@link #celsius()} is always the latest reading; listeners hear a reading only when it differs from the last one
 * they heard by at least the dead band (parameter {@code deadbandCelsius}), so sensor noise does not reach them.
 */
final class SunSpotTemperatureDevice extends AbstractDevice implements TemperatureProvider, BusRadioSunSpotListener {

    static final double DEFAULT_DEADBAND = 0.1;
    /** Absorbs binary rounding, so that 21.6 → 21.7 counts as a step of 0.1. */
    private static final double EPSILON = 1e-9;

    private final BusRadioSunSpotProvider bus;
    private final Listeners<TemperatureListener> listeners;
    private final AtomicLong rejected = new AtomicLong();
    private volatile double deadband = DEFAULT_DEADBAND;
    private volatile Double latest;
    private volatile Instant lastUpdate;
    private Double announced; // guarded by this

    SunSpotTemperatureDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Temperature sensor " + bus.nodeAddress());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeAddress());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.TEMPERATURE});
        publish(this, TemperatureProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioSunSpotProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioSunSpotProvider source, int sensorType, byte[] payload, Instant at) {
        if (sensorType != SunSpotSensorType.TEMPERATURE.code()) {
            return; // other sensors of a multi-sensor node are not ours
        }
        double celsius;
        try {
            SunSpotPayload decoded = SunSpotPayloads.decode(payload);
            if (!(decoded instanceof TemperatureStatus t)) {
                reject("a temperature frame carried " + decoded.getClass().getSimpleName());
                return;
            }
            celsius = t.celsius();
        } catch (SunSpotProtocolException | RuntimeException e) {
            reject(e.getMessage());
            return;
        }
        latest = celsius;
        lastUpdate = at;
        status(DeviceStatus.State.ONLINE, "");
        if (worthAnnouncing(celsius)) {
            listeners.fire(l -> l.temperatureChanged(this, celsius, at));
        }
    }

    private synchronized boolean worthAnnouncing(double celsius) {
        if (announced != null && Math.abs(celsius - announced) < deadband - EPSILON) {
            return false;
        }
        announced = celsius;
        return true;
    }

    private void reject(String reason) {
        rejected.incrementAndGet();
        status(DeviceStatus.State.ERROR, "rejected payload: " + reason);
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(TemperatureListener listener) {
        return listeners.add(listener);
    }

    @Override
    public OptionalDouble celsius() {
        Double c = latest;
        return c == null ? OptionalDouble.empty() : OptionalDouble.of(c);
    }

    double deadband() {
        return deadband;
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("deadbandCelsius", deadband,
                        "listeners hear a reading only if it differs from the last they heard by at least this"),
                Parameter.readOnly("celsius", latest, "latest reading in degrees Celsius"),
                Parameter.readOnly("lastUpdate", lastUpdate, "when the latest reading arrived"),
                Parameter.readOnly("rejectedPayloads", rejected.get(), "temperature payloads that could not be read"));
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

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
