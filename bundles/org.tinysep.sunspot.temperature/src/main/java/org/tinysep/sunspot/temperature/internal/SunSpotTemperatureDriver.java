package org.tinysep.sunspot.temperature.internal;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.ProviderDeviceDriver;

/**
 * Sun SPOT Temperature (thesis 4.4.2.9): one {@link SunSpotTemperatureDevice} per Sun SPOT bus device of node type
 * {@code temperature}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotTemperatureDriver extends ProviderDeviceDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotTemperature";

    public SunSpotTemperatureDriver() {
        super(NAME, BusRadioSunSpotProvider.class,
                "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.TEMPERATURE + ")");
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
    protected AbstractDevice createDevice(BusRadioSunSpotProvider bus) {
        return new SunSpotTemperatureDevice(context(), bus);
    }
}
