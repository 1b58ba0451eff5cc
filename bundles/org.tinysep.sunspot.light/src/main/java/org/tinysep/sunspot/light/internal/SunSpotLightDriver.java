package org.tinysep.sunspot.light.internal;

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
 * Sun SPOT Light (thesis 4.4.2.10): one {@link SunSpotLightDevice} per Sun SPOT bus device of node type
 * {@code light-sensor}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotLightDriver extends ProviderDeviceDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotLight";

    public SunSpotLightDriver() {
        super(NAME, BusRadioSunSpotProvider.class,
                "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.LIGHT_SENSOR + ")");
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
        return new SunSpotLightDevice(context(), bus);
    }
}
