package org.tinysep.sunspot.temperature.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * Sun SPOT Temperature (thesis 4.4.2.9): one {@link SunSpotTemperatureDevice} per Sun SPOT bus device of node type
 * {@code temperature}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotTemperatureDriver extends SensorDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotTemperature";

    public SunSpotTemperatureDriver() {
        super(NAME, BusRadioSunSpotProvider.class, NodeType.TEMPERATURE, SunSpotTemperatureDevice::new);
    }
}
