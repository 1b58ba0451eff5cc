package org.tinysep.amica.door.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * AmICA Door: one {@link AmicaDoorDevice} per AmICA bus device of node type {@code door}; nodes of other
 * types are ignored (thesis Fig 3.3).
 */
@Component(service = {}, immediate = true)
public final class AmicaDoorDriver extends SensorDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaDoor";

    public AmicaDoorDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.DOOR, AmicaDoorDevice::new);
    }
}
