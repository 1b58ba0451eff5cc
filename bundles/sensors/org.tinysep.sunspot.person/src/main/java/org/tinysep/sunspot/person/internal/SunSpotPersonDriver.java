package org.tinysep.sunspot.person.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * Sun SPOT Person: one {@link SunSpotPersonDevice} per Sun SPOT bus device of node type {@code person};
 * nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotPersonDriver extends SensorDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotPerson";

    public SunSpotPersonDriver() {
        super(NAME, BusRadioSunSpotProvider.class, NodeType.PERSON, SunSpotPersonDevice::new);
    }
}
