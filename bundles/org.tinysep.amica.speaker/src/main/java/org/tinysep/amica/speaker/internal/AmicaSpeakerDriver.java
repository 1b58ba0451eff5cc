package org.tinysep.amica.speaker.internal;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.ProviderDeviceDriver;

/**
 * AmICA Speaker (thesis 4.4.2.6): one {@link AmicaSpeakerDevice} per AmICA bus device of node type
 * {@code speaker}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaSpeakerDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaSpeaker";

    public AmicaSpeakerDriver() {
        super(NAME, BusRadioAmicaProvider.class,
                "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.SPEAKER + ")");
    }

    @Activate
    void activate(BundleContext bundleContext) {
        open(bundleContext);
    }

    @Deactivate
    void deactivate() {
        close();
    }

    @Override
    protected AbstractDevice createDevice(BusRadioAmicaProvider bus) {
        return new AmicaSpeakerDevice(context(), bus);
    }
}
