package org.tinysep.amica.dimmablelight.internal;

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
 * AmICA Dimmable Light (thesis 4.4.2.4): one {@link AmicaDimmableLightDevice} per AmICA bus device of node type
 * {@code dimmable-light}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaDimmableLightDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaDimmableLight";

    public AmicaDimmableLightDriver() {
        super(NAME, BusRadioAmicaProvider.class,
                "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.DIMMABLE_LIGHT + ")");
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
        return new AmicaDimmableLightDevice(context(), bus);
    }
}
