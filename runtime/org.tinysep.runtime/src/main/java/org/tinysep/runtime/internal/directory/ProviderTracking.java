package org.tinysep.runtime.internal.directory;

import org.osgi.framework.Constants;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTrackerCustomizer;
import org.tinysep.api.device.DeviceProperties;

/**
 * Keeps the directory's provider services (any service with a {@link DeviceProperties#DEVICE_UID}) in step with
 * the registry. It never gets the service objects: only the objectClass and device UID properties are read.
 */
final class ProviderTracking implements ServiceTrackerCustomizer<Object, ProviderRecord> {

    static final String FILTER = "(" + DeviceProperties.DEVICE_UID + "=*)";

    private final DeviceDirectory directory;

    ProviderTracking(DeviceDirectory directory) {
        this.directory = directory;
    }

    @Override
    public ProviderRecord addingService(ServiceReference<Object> ref) {
        ProviderRecord r = record(ref);
        directory.put(r);
        return r;
    }

    @Override
    public void modifiedService(ServiceReference<Object> ref, ProviderRecord r) {
        directory.put(record(ref));
    }

    @Override
    public void removedService(ServiceReference<Object> ref, ProviderRecord r) {
        directory.removeProvider(r.serviceId());
    }

    private static ProviderRecord record(ServiceReference<?> ref) {
        return ProviderRecord.of(Tracking.serviceId(ref),
                String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID)),
                NodeInfo.strings(ref.getProperty(Constants.OBJECTCLASS)).toArray(String[]::new));
    }
}
