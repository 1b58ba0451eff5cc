package org.tinysep.amica.movement.internal;

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
 * AmICA Movement: one {@link AmicaMovementDevice} per AmICA bus device of node type {@code movement}; nodes of other
 * types are ignored (thesis Fig 3.3).
 */
@Component(service = {}, immediate = true)
public final class AmicaMovementDriver extends ProviderDeviceDriver<BusRadioAmicaProvider> {

    static final String NAME = "AmicaMovement";

    public AmicaMovementDriver() {
        super(NAME, BusRadioAmicaProvider.class, "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.MOVEMENT + ")");
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
        return new AmicaMovementDevice(context(), bus);
    }
}
