package org.tinysep.mqtt.internal;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.DeviceProperties;

/** The services of one interface by their device UID (the {@code tinysep.device.uid} property). */
final class Tracked<S> implements AutoCloseable {

    record Entry<S>(S service, ServiceReference<S> ref) {
    }

    private final Map<String, Entry<S>> byUid = new ConcurrentHashMap<>();
    private final ServiceTracker<S, S> tracker;

    @SuppressWarnings({"unchecked", "rawtypes"})
    Tracked(BundleContext context, Class<?> type) {
        tracker = new ServiceTracker<S, S>(context, (Class) type, null) {
            @Override
            public S addingService(ServiceReference<S> ref) {
                S s = super.addingService(ref);
                Object uid = ref.getProperty(DeviceProperties.DEVICE_UID);
                if (s != null && uid != null) {
                    byUid.put(uid.toString(), new Entry<>(s, ref));
                }
                return s;
            }

            @Override
            public void removedService(ServiceReference<S> ref, S s) {
                Object uid = ref.getProperty(DeviceProperties.DEVICE_UID);
                if (uid != null) {
                    byUid.remove(uid.toString(), new Entry<>(s, ref));
                }
                super.removedService(ref, s);
            }
        };
        tracker.open();
    }

    Map<String, Entry<S>> all() {
        return byUid;
    }

    Entry<S> get(String uid) {
        return byUid.get(uid);
    }

    @Override
    public void close() {
        tracker.close();
    }
}
