package org.tinysep.amica.simplelight.internal;

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
 * AmICA Simple Light (thesis 4.4.2.4): one {@link AmicaSimpleLightDevice} per AmICA bus device of node type
 * {@code simple-light}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaSimpleLightDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaSimpleLight";

    public AmicaSimpleLightDriver() {
        super(NAME, BusRadioAmicaProvider.class,
                "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.SIMPLE_LIGHT + ")");
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
        return new AmicaSimpleLightDevice(context(), bus);
    }
}
