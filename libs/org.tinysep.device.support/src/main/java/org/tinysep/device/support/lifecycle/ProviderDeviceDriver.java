package org.tinysep.device.support.lifecycle;

import org.osgi.framework.BundleContext;

/**
 * The hardware-abstraction pattern: one device per provider of {@code P} that matches a filter (e.g. one
 * AmicaMovement device per AmICA bus device of node type movement). The device is created when the provider
 * appears and removed when it goes (its connection to the provider is vital). Subclasses are DS components
 * whose activate and deactivate methods call {@link #open(BundleContext)} and {@link #close()}.
 *
 * @param <P> the provider interface the devices consume
 */
public abstract class ProviderDeviceDriver<P> extends AbstractDriver implements ProviderTracker.Callback<P> {

    private final Class<P> providerType;
    private final String filter;
    private volatile ProviderTracker<P> tracker;

    /**
     * @param filter LDAP filter on the providers' service properties, or null for all of them
     */
    protected ProviderDeviceDriver(String name, Class<P> providerType, String filter) {
        super(name);
        this.providerType = providerType;
        this.filter = filter;
    }

    /** Starts the driver and creates devices for the matching providers already there. */
    protected final void open(BundleContext bundleContext) {
        start(bundleContext);
        tracker = new ProviderTracker<>(bundleContext, providerType, filter, this).open();
    }

    /** Removes every device, one by one, then the driver. */
    protected final void close() {
        ProviderTracker<P> t = tracker;
        if (t != null) {
            t.close();
        }
        stop();
    }

    /** @return a new, not yet registered device for {@code provider} */
    protected abstract AbstractDevice createDevice(P provider);

    @Override
    public final void added(P provider, String providerDeviceUid) {
        addDevice(createDevice(provider));
    }

    @Override
    public final void removed(P provider, String providerDeviceUid) {
        providerGone(providerDeviceUid);
    }
}
