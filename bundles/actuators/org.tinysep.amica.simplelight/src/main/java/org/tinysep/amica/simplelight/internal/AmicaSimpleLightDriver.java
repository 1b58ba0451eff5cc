package org.tinysep.amica.simplelight.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.NodeTypeDriver;

/**
 * AmICA Simple Light (thesis 4.4.2.4): one {@link AmicaSimpleLightDevice} per AmICA bus device of node type
 * {@code simple-light}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaSimpleLightDriver extends NodeTypeDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaSimpleLight";

    public AmicaSimpleLightDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.SIMPLE_LIGHT, AmicaSimpleLightDevice::new);
    }
}
