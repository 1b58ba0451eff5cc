package org.tinysep.amica.dimmablelight.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.NodeTypeDriver;

/**
 * AmICA Dimmable Light (thesis 4.4.2.4): one {@link AmicaDimmableLightDevice} per AmICA bus device of node type
 * {@code dimmable-light}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaDimmableLightDriver extends NodeTypeDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaDimmableLight";

    public AmicaDimmableLightDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.DIMMABLE_LIGHT, AmicaDimmableLightDevice::new);
    }
}
