package org.tinysep.amica.petmovement.internal;

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
 * AmICA Pet Movement (thesis 4.4.2.7): one {@link AmicaPetMovementDevice} per AmICA bus device of node type
 * {@code pet-collar}; nodes of other types (a person's movement sensor among them) are ignored.
 */
@Component(service = {}, immediate = true)
public final class AmicaPetMovementDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaPetMovement";

    public AmicaPetMovementDriver() {
        super(NAME, BusRadioAmicaProvider.class, "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.PET_COLLAR + ")");
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
        return new AmicaPetMovementDevice(context(), bus);
    }
}
