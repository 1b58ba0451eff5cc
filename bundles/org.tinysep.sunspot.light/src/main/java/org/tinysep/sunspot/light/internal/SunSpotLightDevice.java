package org.tinysep.sunspot.light.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.LightBrightnessListener;
import org.tinysep.api.sensor.LightBrightnessProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT light sensor: Light Status payloads become brightness percentages. A sensor only: the
 * Sun SPOT light node has no actuator (thesis 4.4.2.10), so nothing is ever sent back. Listeners hear changes; the
 * node repeats its reading every 10 s.
 */
final class SunSpotLightDevice extends AbstractDevice implements LightBrightnessProvider, BusRadioSunSpotListener {

    private final BusRadioSunSpotProvider bus;
    private final Listeners<LightBrightnessListener> listeners;
    private final AtomicLong rejected = new AtomicLong();
    private volatile Percent brightness;
    private volatile Instant lastUpdate;

    SunSpotLightDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Light sensor " + bus.nodeAddress());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeAddress());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.LIGHT_SENSOR});
        publish(this, LightBrightnessProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioSunSpotProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioSunSpotProvider source, int sensorType, byte[] payload, Instant at) {
        if (sensorType != SunSpotSensorType.LIGHT.code()) {
            return; // other sensors of a multi-sensor node are not ours
        }
        Percent next;
        try {
            SunSpotPayload decoded = SunSpotPayloads.decode(payload);
            if (!(decoded instanceof LightStatus light)) {
                reject("a light frame carried " + decoded.getClass().getSimpleName());
                return;
            }
            next = Percent.of(light.percent());
        } catch (SunSpotProtocolException | RuntimeException e) {
            reject(e.getMessage());
            return;
        }
        lastUpdate = at;
        status(DeviceStatus.State.ONLINE, "");
        if (next.equals(brightness)) {
            return;
        }
        brightness = next;
        listeners.fire(l -> l.brightnessChanged(this, next, at));
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
    public Connection connect(LightBrightnessListener listener) {
        return listeners.add(listener);
    }

    @Override
    public Optional<Percent> brightness() {
        return Optional.ofNullable(brightness);
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.readOnly("brightness", brightness, "latest brightness"),
                Parameter.readOnly("lastUpdate", lastUpdate, "when the latest reading arrived"),
                Parameter.readOnly("rejectedPayloads", rejected.get(), "light payloads that could not be read"));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
