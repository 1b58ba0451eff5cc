package org.tinysep.sunspot.petmovement.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * Sun SPOT Pet Movement (thesis 4.4.2.11): one {@link SunSpotPetMovementDevice} per Sun SPOT bus device of node type
 * {@code pet-collar}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotPetMovementDriver extends SensorDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotPetMovement";

    public SunSpotPetMovementDriver() {
        super(NAME, BusRadioSunSpotProvider.class, NodeType.PET_COLLAR, SunSpotPetMovementDevice::new);
    }
}
