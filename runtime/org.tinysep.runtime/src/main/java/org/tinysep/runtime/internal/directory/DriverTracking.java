package org.tinysep.runtime.internal.directory;

import java.util.function.BooleanSupplier;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTrackerCustomizer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.device.support.lifecycle.Safely;

/** Keeps the directory's drivers in step with the registry and announces each arrival and departure. */
final class DriverTracking implements ServiceTrackerCustomizer<Driver, DriverRecord> {

    private static final Logger LOG = LoggerFactory.getLogger(DriverTracking.class);

    private final BundleContext context;
    private final DeviceDirectory directory;
    private final Announcer announcer;
    private final BooleanSupplier closing;

    DriverTracking(BundleContext context, DeviceDirectory directory, Announcer announcer, BooleanSupplier closing) {
        this.context = context;
        this.directory = directory;
        this.announcer = announcer;
        this.closing = closing;
    }

    /**
     * Announces the driver from its service properties before getting the service object, because getting it may
     * activate the driver, which may at once create devices: the log then reads driver first, devices after.
     */
    @Override
    public DriverRecord addingService(ServiceReference<Driver> ref) {
        long serviceId = Tracking.serviceId(ref);
        Bundle bundle = ref.getBundle();
        long bundleId = bundle == null ? -1 : bundle.getBundleId();
        String bundleName = bundle == null ? "" : bundle.getSymbolicName();
        String uid = Tracking.string(ref, DeviceProperties.DRIVER_UID, () -> null);
        String name = Tracking.string(ref, DeviceProperties.DRIVER_NAME, () -> null);
        boolean announced = !uid.isEmpty() && !name.isEmpty();
        if (announced) {
            announcer.driverAdded(new DriverRecord(serviceId, uid, name, bundleId, bundleName, null));
        }
        Driver driver = context.getService(ref);
        if (driver == null) {
            LOG.warn("Driver service {} ({}) of bundle {} could not be obtained; ignored", serviceId, name, bundleId);
            if (announced) {
                announcer.problem(uid, "driver " + name + " could not be obtained (did its activation fail?)");
            }
            return null;
        }
        DriverRecord r = new DriverRecord(serviceId, Safely.get(driver::uid, uid), Safely.get(driver::name, name),
                bundleId, bundleName, driver);
        directory.put(r);
        if (!announced) {
            announcer.driverAdded(r);
        }
        return r;
    }

    @Override
    public void modifiedService(ServiceReference<Driver> ref, DriverRecord r) {
        // UID and name are fixed for the life of a driver
    }

    @Override
    public void removedService(ServiceReference<Driver> ref, DriverRecord r) {
        directory.removeDriver(r.serviceId());
        if (!closing.getAsBoolean()) {
            announcer.driverRemoved(r);
        }
        Tracking.unget(context, ref);
    }
}
