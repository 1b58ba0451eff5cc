package org.tinysep.followmelight.internal;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.device.support.rooms.Placements;

/**
 * The room of every light: the {@code tinysep.room} property of its light services, read when one is registered,
 * modified (the user placed the light, or its room left the house plan) or unregistered, from the service's own
 * reference, so it is right whichever registry listener hears the change first. Each change is told to
 * {@code moved} (Follow Me Light re-files the light in its lights-by-room index). Names come from {@code names}.
 */
final class LightRooms implements Placements, AutoCloseable {

    private final Map<String, Optional<String>> rooms = new ConcurrentHashMap<>();
    private final Placements names;
    private final ServiceTracker<Object, String> tracker;

    LightRooms(BundleContext context, Placements names, Consumer<String> moved) {
        this.names = names;
        String filter = "(&(" + DeviceProperties.DEVICE_UID + "=*)(|(" + Constants.OBJECTCLASS + "="
                + SimpleLightProvider.class.getName() + ")(" + Constants.OBJECTCLASS + "="
                + DimmableLightProvider.class.getName() + ")))";
        try {
            tracker = new ServiceTracker<>(context, FrameworkUtil.createFilter(filter), null) {
                @Override
                public String addingService(ServiceReference<Object> ref) {
                    String uid = uidOf(ref);
                    rooms.put(uid, roomOf(ref));
                    moved.accept(uid);
                    return uid;
                }

                @Override
                public void modifiedService(ServiceReference<Object> ref, String uid) {
                    rooms.put(uid, roomOf(ref));
                    moved.accept(uid);
                }

                @Override
                public void removedService(ServiceReference<Object> ref, String uid) {
                    Optional<String> left = null; // another light service of the same device may stay
                    ServiceReference<Object>[] refs = getServiceReferences();
                    for (int i = 0; refs != null && i < refs.length; i++) {
                        if (!refs[i].equals(ref) && uid.equals(uidOf(refs[i]))) {
                            left = roomOf(refs[i]);
                        }
                    }
                    if (left == null) {
                        rooms.remove(uid);
                    } else {
                        rooms.put(uid, left);
                    }
                    moved.accept(uid);
                }
            };
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        tracker.open();
    }

    private static String uidOf(ServiceReference<?> ref) {
        return String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID));
    }

    private static Optional<String> roomOf(ServiceReference<?> ref) {
        Object room = ref.getProperty(DeviceProperties.ROOM);
        return room == null || room.toString().isBlank() ? Optional.empty() : Optional.of(room.toString());
    }

    @Override
    public Optional<String> roomOf(String lightUid) {
        return rooms.getOrDefault(lightUid, Optional.empty());
    }

    @Override
    public String nameOf(String deviceUid) {
        return names.nameOf(deviceUid);
    }

    @Override
    public void close() {
        tracker.close();
        rooms.clear();
    }
}
