package org.tinysep.runtime.internal.directory;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.SynchronousBundleListener;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Driver;
import org.tinysep.api.log.EventLog;

/**
 * The device manager (thesis 3.3, 4.3). It watches the service registry, which does the announcing of interfaces
 * to drivers and devices, and keeps an inventory of every driver, device and provided interface for the shell.
 * It records drivers and devices coming and going in the event log. It never carries device-to-device events.
 * <p>
 * Service events may arrive on any thread, including synchronously on a bus radio's receive thread: the
 * trackers only update lock-free maps and append to the event log, so they never block.
 */
// name: the component name (and PID) it had before the runtime was split into packages
@Component(name = "org.tinysep.runtime.internal.DeviceManager",
        service = Inventory.class, immediate = true)
public final class DeviceManager implements Inventory {

    private final DeviceDirectory directory = new DeviceDirectory();
    private final AtomicBoolean closing = new AtomicBoolean();
    private final List<ServiceTracker<?, ?>> trackers = new ArrayList<>();
    private BundleContext context;
    /**
     * Told synchronously when the framework begins to stop, before any bundle stops: the trackers let go of every
     * device service then. Felix keeps each bundle's service uses in an array it scans on every unregistration, so
     * while this bundle (start level 4) held a service object per device, stopping 10,000 devices at level 5 was
     * quadratic: ~26 s of a 10,000-device stop in Felix's {@code getUsingBundles}/{@code flushUsageCount} (JFR).
     * The directory is empty from then on; nothing is announced (the platform is stopping).
     */
    private final SynchronousBundleListener frameworkStopping = e -> {
        if (e.getType() == BundleEvent.STOPPING && e.getBundle().getBundleId() == 0) {
            release();
        }
    };

    @Reference
    private EventLog eventLog;

    @Activate
    void activate(BundleContext context) throws InvalidSyntaxException {
        this.context = context;
        Announcer announcer = new Announcer(eventLog);
        // Providers first, so that devices already registered are announced with their interfaces.
        ServiceTracker<Object, ProviderRecord> providers = new ServiceTracker<>(context,
                context.createFilter(ProviderTracking.FILTER), new ProviderTracking(directory));
        ServiceTracker<Driver, DriverRecord> drivers = new ServiceTracker<>(context, Driver.class,
                new DriverTracking(context, directory, announcer, closing::get));
        ServiceTracker<Device, DeviceRecord> devices = new ServiceTracker<>(context, Device.class,
                new DeviceTracking(context, directory, announcer, closing::get));
        providers.open(true); // all of them, whatever API version they were built against: no object is used
        trackers.add(providers);
        drivers.open();
        trackers.add(drivers);
        devices.open();
        trackers.add(devices);
        context.addBundleListener(frameworkStopping);
    }

    @Deactivate
    void deactivate() {
        try {
            context.removeBundleListener(frameworkStopping);
        } catch (IllegalStateException stopping) {
            // the bundle is already stopping
        }
        release();
    }

    /** Closes the trackers (each once): every service object is given back. */
    private synchronized void release() {
        closing.set(true); // the platform is stopping: closing the trackers is not a removal to announce
        for (int i = trackers.size() - 1; i >= 0; i--) {
            trackers.get(i).close();
        }
        trackers.clear();
    }

    /** @return whether the trackers were closed (the framework is stopping, or this component is) */
    boolean released() {
        return closing.get();
    }

    @Override
    public List<DriverRecord> drivers() {
        return directory.drivers();
    }

    @Override
    public List<DeviceRecord> devices() {
        return directory.devices();
    }

    @Override
    public List<String> interfacesOf(String deviceUid) {
        return directory.interfacesOf(deviceUid);
    }
}
