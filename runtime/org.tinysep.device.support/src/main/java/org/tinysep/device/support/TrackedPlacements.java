package org.tinysep.device.support;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;

/**
 * A {@link Placements} over the service registry: every service carrying {@code tinysep.device.uid}. Service
 * references show property modifications live, so the room read here is the one the device has right now.
 */
public final class TrackedPlacements implements Placements, AutoCloseable {

    private final ServiceTracker<Object, ServiceReference<Object>> tracker;
    private final BundleContext context;

    public TrackedPlacements(BundleContext context) {
        this.context = context;
        try {
            tracker = new ServiceTracker<>(context,
                    FrameworkUtil.createFilter("(" + DeviceProperties.DEVICE_UID + "=*)"), null) {
                @Override
                public ServiceReference<Object> addingService(ServiceReference<Object> ref) {
                    return ref;
                }

                @Override
                public void removedService(ServiceReference<Object> ref, ServiceReference<Object> same) {
                    // nothing was got, nothing to release
                }
            };
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        tracker.open();
    }

    @Override
    public Optional<String> roomOf(String deviceUid) {
        for (ServiceReference<Object> ref : references(deviceUid)) {
            Object room = ref.getProperty(DeviceProperties.ROOM);
            if (room != null && !room.toString().isBlank()) {
                return Optional.of(room.toString());
            }
        }
        return Optional.empty();
    }

    @Override
    public String nameOf(String deviceUid) {
        for (ServiceReference<Object> ref : references(deviceUid)) {
            if (isDevice(ref)) {
                Object d = context.getService(ref);
                try {
                    if (d instanceof Device device) {
                        return device.name();
                    }
                } finally {
                    if (d != null) {
                        context.ungetService(ref);
                    }
                }
            }
        }
        return deviceUid;
    }

    private List<ServiceReference<Object>> references(String deviceUid) {
        ServiceReference<Object>[] refs = tracker.getServiceReferences();
        List<ServiceReference<Object>> out = new ArrayList<>();
        if (refs != null) {
            for (ServiceReference<Object> r : refs) {
                if (deviceUid.equals(String.valueOf(r.getProperty(DeviceProperties.DEVICE_UID)))) {
                    out.add(r);
                }
            }
        }
        return out;
    }

    private static boolean isDevice(ServiceReference<?> ref) {
        Object classes = ref.getProperty(Constants.OBJECTCLASS);
        if (classes instanceof String[] names) {
            for (String n : names) {
                if (Device.class.getName().equals(n)) {
                    return true;
                }
            }
        }
        return false;
    }

    @Override
    public void close() {
        tracker.close();
    }
}
