package org.tinysep.amica.movement.internal;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.AbstractDriver;
import org.tinysep.device.support.ProviderTracker;

/**
 * AmICA Movement (thesis 4.4.2.1): one {@link AmicaMovementDevice} per AmICA bus device of node type
 * {@code movement}; nodes of other types are ignored (thesis Fig 3.3).
 */
@Component(service = {}, immediate = true)
public final class AmicaMovementDriver extends AbstractDriver
        implements ProviderTracker.Callback<BusRadioAmicaProvider> {

    static final String NAME = "AmicaMovement";
    static final String FILTER = "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.MOVEMENT + ")";

    private ProviderTracker<BusRadioAmicaProvider> buses;

    public AmicaMovementDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext) {
        start(bundleContext);
        buses = new ProviderTracker<>(bundleContext, BusRadioAmicaProvider.class, FILTER, this).open();
    }

    @Deactivate
    void deactivate() {
        buses.close();
        stop();
    }

    @Override
    public void added(BusRadioAmicaProvider bus, String busUid) {
        addDevice(new AmicaMovementDevice(context(), bus));
    }

    @Override
    public void removed(BusRadioAmicaProvider bus, String busUid) {
        providerGone(busUid);
    }
}
