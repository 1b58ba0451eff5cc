package org.tinysep.sunspot.movement.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * Sun SPOT Movement (thesis 4.4.2.8): one {@link SunSpotMovementDevice} per Sun SPOT bus device of node type
 * {@code movement}; nodes of other types are ignored (thesis Fig 3.6).
 */
@Component(service = {}, immediate = true)
public final class SunSpotMovementDriver extends SensorDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotMovement";

    public SunSpotMovementDriver() {
        super(NAME, BusRadioSunSpotProvider.class, NodeType.MOVEMENT, SunSpotMovementDevice::new);
    }
}
