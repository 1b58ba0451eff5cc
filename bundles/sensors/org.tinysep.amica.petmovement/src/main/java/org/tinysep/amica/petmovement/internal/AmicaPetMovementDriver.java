package org.tinysep.amica.petmovement.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * AmICA Pet Movement (thesis 4.4.2.7): one {@link AmicaPetMovementDevice} per AmICA bus device of node type
 * {@code pet-collar}; nodes of other types (a person's movement sensor among them) are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaPetMovementDriver extends SensorDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaPetMovement";

    public AmicaPetMovementDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.PET_COLLAR, AmicaPetMovementDevice::new);
    }
}
