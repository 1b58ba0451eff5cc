package org.tinysep.runtime.internal.directory;

import java.util.function.BooleanSupplier;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTrackerCustomizer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.device.support.lifecycle.ServiceUse;
import org.tinysep.device.support.lifecycle.Safely;

/**
 * Keeps the directory's devices in step with the registry and announces creation and removal. A device's
 * interfaces are those of its provider services registered before its Device service (the order the device
 * support library uses); later ones show in {@code devices} but not in the creation entry.
 */
final class DeviceTracking implements ServiceTrackerCustomizer<Device, DeviceRecord> {

    private static final Logger LOG = LoggerFactory.getLogger(DeviceTracking.class);

    private final BundleContext context;
    private final DeviceDirectory directory;
    private final Announcer announcer;
    private final BooleanSupplier closing;

    DeviceTracking(BundleContext context, DeviceDirectory directory, Announcer announcer, BooleanSupplier closing) {
        this.context = context;
        this.directory = directory;
        this.announcer = announcer;
        this.closing = closing;
    }

    @Override
    public DeviceRecord addingService(ServiceReference<Device> ref) {
        // kept without a use left in the registry: Felix's per-bundle use array made n devices cost n²
        Device device = ServiceUse.take(context, ref);
        if (device == null) {
            LOG.warn("Device service {} could not be obtained; ignored", ref.getProperty(Constants.SERVICE_ID));
            return null;
        }
        String uid = Tracking.string(ref, DeviceProperties.DEVICE_UID, () -> device.uid());
        String type = Tracking.string(ref, DeviceProperties.DEVICE_TYPE, () -> device.type());
        String driverUid = Tracking.string(ref, DeviceProperties.DRIVER_UID, () -> device.driverUid());
        String name = Safely.get(device::name, type);
        DeviceRecord r = new DeviceRecord(Tracking.serviceId(ref), uid, type, name, driverUid,
                NodeInfo.from(ref::getProperty), device);
        directory.put(r);
        announcer.deviceCreated(r, directory.interfacesOf(uid));
        return r;
    }

    @Override
    public void modifiedService(ServiceReference<Device> ref, DeviceRecord r) {
        directory.put(r.withNode(NodeInfo.from(ref::getProperty)));
    }

    @Override
    public void removedService(ServiceReference<Device> ref, DeviceRecord r) {
        directory.removeDevice(r.serviceId());
        if (!closing.getAsBoolean()) {
            announcer.deviceRemoved(r);
        }
        ServiceUse.release(context, ref);
    }
}
