package org.tinysep.amica.window.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * AmICA Window (thesis 4.4.2.3): one {@link AmicaWindowDevice} per AmICA bus device of node type {@code window};
 * nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaWindowDriver extends SensorDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaWindow";

    public AmicaWindowDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.WINDOW, AmicaWindowDevice::new);
    }
}
