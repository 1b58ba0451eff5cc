package org.tinysep.amica.heater.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.NodeTypeDriver;

/**
 * AmICA Heater (thesis 4.4.2.5): one {@link AmicaHeaterDevice} per AmICA bus device of node type
 * {@code heater}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaHeaterDriver extends NodeTypeDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaHeater";

    public AmicaHeaterDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.HEATER, AmicaHeaterDevice::new);
    }
}
