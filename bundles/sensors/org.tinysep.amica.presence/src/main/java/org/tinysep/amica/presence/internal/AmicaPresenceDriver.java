package org.tinysep.amica.presence.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.sensor.SensorDriver;

/**
 * AmICA Presence: one {@link AmicaPresenceDevice} per AmICA bus device whose node types include a presence type
 * ({@code presence-bed}, {@code presence-seat}, {@code presence-flush}, {@code presence-appliance}: the TinySEP
 * extension of the product id, bits 8..11); the filter matches the common prefix. Nodes of other types are ignored
 * (thesis Fig 3.3).
 */
@Component(service = {}, immediate = true)
public final class AmicaPresenceDriver extends SensorDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaPresence";

    public AmicaPresenceDriver() {
        super(NAME, BusRadioAmicaProvider.class, NodeType.PRESENCE_PREFIX + "*", AmicaPresenceDevice::new);
    }
}
