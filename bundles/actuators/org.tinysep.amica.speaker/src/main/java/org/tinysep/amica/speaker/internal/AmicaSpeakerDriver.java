package org.tinysep.amica.speaker.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.NodeTypeDriver;

/**
 * AmICA Speaker (thesis 4.4.2.6): one {@link AmicaSpeakerDevice} per AmICA bus device of node type
 * {@code speaker}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaSpeakerDriver extends NodeTypeDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaSpeaker";

    public AmicaSpeakerDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.SPEAKER, AmicaSpeakerDevice::new);
    }
}
