package org.tinysep.device.support.rooms;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.device.support.lifecycle.ServiceUse;

/**
 * A {@link Placements} over the service registry: every {@link Device} service, indexed by its
 * {@code tinysep.device.uid} when it is registered, so a lookup reads only that device's service (a scan of every
 * device's services per lookup was most of the packet → reaction latency, since Follow Me Light asks for the room
 * of every light per motion). The room is read from the service's properties only when it is registered, modified
 * or unregistered (the tracker's callbacks run before {@code setProperties} returns), and kept per UID: a lookup is a
 * map read, not a walk through Felix's case-insensitive property maps, which was 18 % of the AmICA delivery thread
 * at the throughput limit (issue 29). Whoever keeps its own index by room (Follow Me Light's lights by room) is told
 * each device whose room changed, once the new room is kept here.
 */
public final class TrackedPlacements implements Placements, AutoCloseable {

    /**
     * The {@link Device} services only, one per device: the device support library registers a device's services
     * with the same properties ({@code DeviceServices}), so its Device service names its room. Tracking every
     * service with a device UID took each device's 2 services (3 room reads each as the second joined the first),
     * and its initial walk could not use Felix's objectClass index: with 20,000 services, each of the three
     * bundles opening one at the start matched the filter against every service (issue 29, item 4).
     */
    static final String FILTER = "(&(" + Constants.OBJECTCLASS + "=" + Device.class.getName() + ")("
            + DeviceProperties.DEVICE_UID + "=*))";

    private final Map<String, List<ServiceReference<Object>>> byUid = new ConcurrentHashMap<>();
    private final Map<String, Optional<String>> roomByUid = new ConcurrentHashMap<>();
    /** How often a room was read from service properties (tests: none per lookup). */
    private final AtomicLong propertyReads = new AtomicLong();
    private final ServiceTracker<Object, String> tracker;
    private final BundleContext context;
    private final Consumer<String> roomChanged;
    private volatile boolean closing;

    public TrackedPlacements(BundleContext context) {
        this(context, uid -> { });
    }

    /**
     * @param roomChanged told the UID of a device that was placed, moved, unplaced or left, after its room is kept
     *                    here (on the registry's thread, also while this constructor opens the tracker)
     */
    public TrackedPlacements(BundleContext context, Consumer<String> roomChanged) {
        this.context = context;
        this.roomChanged = roomChanged;
        try {
            tracker = new ServiceTracker<>(context,
                    FrameworkUtil.createFilter(FILTER), null) {
                @Override
                public String addingService(ServiceReference<Object> ref) {
                    String uid = uidOf(ref);
                    byUid.merge(uid, List.of(ref), TrackedPlacements::plus);
                    reindex(uid);
                    return uid;
                }

                @Override
                public void modifiedService(ServiceReference<Object> ref, String indexedAs) {
                    String uid = uidOf(ref);
                    if (!uid.equals(indexedAs)) { // a UID does not change in practice; keep the index true anyway
                        forget(indexedAs, ref);
                        byUid.merge(uid, List.of(ref), TrackedPlacements::plus);
                        reindex(indexedAs);
                    }
                    reindex(uid); // the room may have changed
                }

                @Override
                public void removedService(ServiceReference<Object> ref, String indexedAs) {
                    if (closing) {
                        return; // every device is reported removed: the whole index goes at once
                    }
                    forget(indexedAs, ref);
                    forget(uidOf(ref), ref); // the tracker keeps the UID it was added under
                    reindex(indexedAs);
                    reindex(uidOf(ref));
                }
            };
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        tracker.open();
    }

    @Override
    public Optional<String> roomOf(String deviceUid) {
        return roomByUid.getOrDefault(deviceUid, Optional.empty());
    }

    /** The room of {@code uid} read again from its services' properties (the first that names one). */
    private void reindex(String uid) {
        Optional<String> before = roomByUid.get(uid);
        Optional<String> after = roomByUid.compute(uid, (k, old) -> {
            for (ServiceReference<Object> ref : byUid.getOrDefault(k, List.of())) {
                propertyReads.incrementAndGet();
                Object room = ref.getProperty(DeviceProperties.ROOM);
                if (room != null && !room.toString().isBlank()) {
                    return Optional.of(room.toString());
                }
            }
            return null; // no service of it names a room: nothing kept
        });
        if (!Objects.equals(before, after)) {
            roomChanged.accept(uid);
        }
    }

    /** @return how often a room was read from service properties since this object was made */
    long propertyReads() {
        return propertyReads.get();
    }

    @Override
    public String nameOf(String deviceUid) {
        for (ServiceReference<Object> ref : byUid.getOrDefault(deviceUid, List.of())) {
            String name = ServiceUse.with(context, ref, d -> d instanceof Device device ? device.name() : null, null);
            if (name != null) {
                return name;
            }
        }
        return deviceUid;
    }

    private void forget(String uid, ServiceReference<Object> ref) {
        byUid.computeIfPresent(uid, (k, refs) -> {
            List<ServiceReference<Object>> rest = refs.stream().filter(r -> !r.equals(ref)).toList();
            return rest.isEmpty() ? null : rest;
        });
    }

    private static List<ServiceReference<Object>> plus(List<ServiceReference<Object>> a,
            List<ServiceReference<Object>> b) {
        return Stream.concat(a.stream(), b.stream().filter(r -> !a.contains(r))).toList();
    }

    private static String uidOf(ServiceReference<?> ref) {
        return String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID));
    }

    @Override
    public void close() {
        // the tracker's close reports every device as removed: re-indexing each and telling whoever follows the rooms
        // was a quarter of the CPU of an orderly stop of 20,000 devices (three bundles each hold one; issue 29)
        closing = true;
        tracker.close();
        byUid.clear();
        roomByUid.clear();
    }
}
