package org.tinysep.sunspot.light.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * Sun SPOT Light (thesis 4.4.2.10): one {@link SunSpotLightDevice} per Sun SPOT bus device of node type
 * {@code light-sensor}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotLightDriver extends SensorDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotLight";

    public SunSpotLightDriver() {
        super(NAME, BusRadioSunSpotProvider.class, NodeType.LIGHT_SENSOR, SunSpotLightDevice::new);
    }
}
