package org.tinysep.sunspot.movement.internal;

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
 * Sun SPOT Movement (thesis 4.4.2.8): one {@link SunSpotMovementDevice} per Sun SPOT bus device of node type
 * {@code movement}; nodes of other types are ignored (thesis Fig 3.6).
 */
@Component(service = {}, immediate = true)
public final class SunSpotMovementDriver extends ProviderDeviceDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotMovement";

    public SunSpotMovementDriver() {
        super(NAME, BusRadioSunSpotProvider.class, "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.MOVEMENT + ")");
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
        return new SunSpotMovementDevice(context(), bus);
    }
}
