package org.tinysep.amica.heater.internal;

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
 * AmICA Heater (thesis 4.4.2.5): one {@link AmicaHeaterDevice} per AmICA bus device of node type
 * {@code heater}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaHeaterDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaHeater";

    public AmicaHeaterDriver() {
        super(NAME, BusRadioAmicaProvider.class,
                "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.HEATER + ")");
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
        return new AmicaHeaterDevice(context(), bus);
    }
}
