package org.tinysep.amica.movement.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * AmICA Movement: one {@link AmicaMovementDevice} per AmICA bus device of node type {@code movement}; nodes of other
 * types are ignored (thesis Fig 3.3).
 */
@Component(service = {}, immediate = true)
public final class AmicaMovementDriver extends SensorDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaMovement";

    public AmicaMovementDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.MOVEMENT, AmicaMovementDevice::new);
    }
}
