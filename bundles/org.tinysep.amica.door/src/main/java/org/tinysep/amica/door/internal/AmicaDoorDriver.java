package org.tinysep.amica.door.internal;

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
 * AmICA Door (thesis 4.4.2.2): one {@link AmicaDoorDevice} per AmICA bus device of node type {@code door}.
 */
@Component(service = {}, immediate = true)
public final class AmicaDoorDriver extends AbstractDriver implements ProviderTracker.Callback<BusRadioAmicaProvider> {

    static final String NAME = "AmicaDoor";
    static final String FILTER = "(" + DeviceProperties.NODE_TYPE + "=" + NodeType.DOOR + ")";

    private ProviderTracker<BusRadioAmicaProvider> buses;

    public AmicaDoorDriver() {
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
        addDevice(new AmicaDoorDevice(context(), bus));
    }

    @Override
    public void removed(BusRadioAmicaProvider bus, String busUid) {
        providerGone(busUid);
    }
}
