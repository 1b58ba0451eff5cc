package org.tinysep.sunspot.petmovement.internal;

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
 * Sun SPOT Pet Movement (thesis 4.4.2.11): one {@link SunSpotPetMovementDevice} per Sun SPOT bus device of node type
 * {@code pet-collar}; nodes of other types are ignored.
 */
@Component(service = {}, immediate = true)
public final class SunSpotPetMovementDriver extends ProviderDeviceDriver<BusRadioSunSpotProvider> {

    static final String NAME = "SunSpotPetMovement";

    public SunSpotPetMovementDriver() {
        super(NAME, BusRadioSunSpotProvider.class, "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.PET_COLLAR + ")");
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
        return new SunSpotPetMovementDevice(context(), bus);
    }
}
