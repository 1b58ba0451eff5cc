package org.tinysep.amica.window.internal;

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
 * AmICA Window (thesis 4.4.2.3): one {@link AmicaWindowDevice} per AmICA bus device of node type {@code window};
 * nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaWindowDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaWindow";

    public AmicaWindowDriver() {
        super(NAME, BusRadioAmicaProvider.class, "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.WINDOW + ")");
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
        return new AmicaWindowDevice(context(), bus);
    }
}
