package org.tinysep.sunspot.light.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.LightBrightnessListener;
import org.tinysep.api.sensor.LightBrightnessProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.SensorDevice;
import org.tinysep.device.support.sensor.Source;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT light sensor: Light Status payloads become brightness percentages. A sensor only: the
 * Sun SPOT light node has no actuator (thesis 4.4.2.10), so nothing is ever sent back. Listeners hear changes; the
 * node repeats its reading every 10 s.
 */
final class SunSpotLightDevice extends SensorDevice<LightBrightnessListener, Percent>
        implements LightBrightnessProvider {

    private static final Source.Frames FRAMES = new Source.Frames(SunSpotSensorType.LIGHT.code(), "light");

    SunSpotLightDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Source.sunSpot(bus, FRAMES, SunSpotPayloads::decode, LightStatus.class,
                (light, at) -> Percent.of(light.percent())), NodeType.LIGHT_SENSOR,
                "Light sensor " + bus.nodeAddress(), LightBrightnessProvider.class);
    }

    @Override
    protected void tell(LightBrightnessListener listener, Percent brightness, boolean first, Instant at) {
        listener.brightnessChanged(this, brightness, at);
    }

    @Override
    public Optional<Percent> brightness() {
        return Optional.ofNullable(latest());
    }

    @Override
    protected List<Parameter> readings() {
        return List.of(Parameter.readOnly("brightness", latest(), "latest brightness"),
                Parameter.readOnly("lastUpdate", lastUpdate(), "when the latest reading arrived"));
    }
}
