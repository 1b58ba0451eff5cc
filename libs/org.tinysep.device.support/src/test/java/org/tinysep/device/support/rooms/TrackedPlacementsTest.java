package org.tinysep.device.support.rooms;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.util.Hashtable;
import java.util.Map;
import java.util.Optional;
import org.apache.felix.framework.FrameworkFactory;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceRegistration;
import org.osgi.framework.launch.Framework;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;

/** Placements read from a real Felix service registry, indexed by device UID (issue 14). */
class TrackedPlacementsTest {

    @TempDir
    Path storage;
    private Framework fw;
    private BundleContext context;

    @BeforeEach
    void start() throws Exception {
        fw = new FrameworkFactory().newFramework(Map.of(Constants.FRAMEWORK_STORAGE, storage.toString(),
                Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT));
        fw.start();
        context = fw.getBundleContext();
    }

    @AfterEach
    void stop() throws Exception {
        fw.stop();
        fw.waitForStop(30_000);
    }

    @Test
    void aDevicesRoomAndNameComeFromItsOwnServicesAndFollowChangesLive() {
        for (int i = 0; i < 300; i++) { // other devices, before and after the one asked about
            register("other-" + i, "room-" + i);
        }
        ServiceRegistration<?> device = register("lamp", "kitchen");
        ServiceRegistration<?> provider = provider("lamp", null); // a second service of the same device, no room
        try (TrackedPlacements placements = new TrackedPlacements(context)) {
            assertEquals(Optional.of("kitchen"), placements.roomOf("lamp"));
            assertEquals("Lamp lamp", placements.nameOf("lamp"));
            assertEquals(Optional.of("room-299"), placements.roomOf("other-299"));

            device.setProperties(props("lamp", "hall")); // moved at run time
            assertEquals(Optional.of("hall"), placements.roomOf("lamp"));

            ServiceRegistration<?> later = register("late", "bedroom"); // registered after the tracker opened
            assertEquals(Optional.of("bedroom"), placements.roomOf("late"));
            later.unregister();
            assertEquals(Optional.empty(), placements.roomOf("late"));
            assertEquals("late", placements.nameOf("late"), "an unknown device is named by its UID");

            provider.setProperties(props("lamp", "study")); // a provider service alone does not place a device
            assertEquals(Optional.of("hall"), placements.roomOf("lamp"));
            device.unregister();
            assertEquals(Optional.empty(), placements.roomOf("lamp"), "the device left");
            provider.unregister();
            assertEquals(Optional.empty(), placements.roomOf("lamp"));
            assertEquals(Optional.of("room-7"), placements.roomOf("other-7"));
        }
    }

    /**
     * Issue 29, item 4: a device registers its Device service and a provider service with the same properties; only
     * the Device service is tracked, so each device costs one room read when the tracker opens over n devices and one
     * per device registered later, at n as at 2n.
     */
    @Test
    void eachDeviceCostsOneRoomReadWhateverItsNumberOfServices() {
        for (int i = 0; i < 200; i++) {
            register("light-" + i, "room-" + i);
            provider("light-" + i, "room-" + i);
        }
        try (TrackedPlacements placements = new TrackedPlacements(context)) {
            assertEquals(200, placements.propertyReads(), "room reads opening over 200 devices of 2 services each");
            for (int i = 200; i < 600; i++) {
                register("light-" + i, "room-" + i);
                provider("light-" + i, "room-" + i);
            }
            assertEquals(600, placements.propertyReads(), "room reads after 400 devices more");
            assertEquals(Optional.of("room-599"), placements.roomOf("light-599"));
        }
    }

    @Test
    void aLookupReadsNoServicePropertiesOnlyAChangeDoes() {
        for (int i = 0; i < 40; i++) {
            register("light-" + i, "room-" + i);
        }
        ServiceRegistration<?> lamp = register("lamp", "kitchen");
        try (TrackedPlacements placements = new TrackedPlacements(context)) {
            long before = placements.propertyReads();
            for (int motion = 0; motion < 1_000; motion++) { // Follow Me Light: the room of every light per motion
                for (int i = 0; i < 40; i++) {
                    assertEquals(Optional.of("room-" + i), placements.roomOf("light-" + i));
                }
            }
            assertEquals(0, placements.propertyReads() - before, "property reads for 40,000 room lookups");
            lamp.setProperties(props("lamp", "hall"));
            assertEquals(Optional.of("hall"), placements.roomOf("lamp"));
            assertEquals(1, placements.propertyReads() - before, "property reads for one room change");
        }
    }

    /** Follow Me Light keeps its lights by room: it is told each device whose room changed, after the change is kept. */
    @Test
    void aRoomChangeIsToldOnceItIsKept() {
        ServiceRegistration<?> lamp = register("lamp", "kitchen");
        java.util.List<String> told = new java.util.ArrayList<>();
        TrackedPlacements[] self = new TrackedPlacements[1];
        try (TrackedPlacements placements = new TrackedPlacements(context,
                uid -> told.add(uid + "=" + (self[0] == null ? "opening" : self[0].roomOf(uid).orElse("-"))))) {
            self[0] = placements;
            assertEquals(java.util.List.of("lamp=opening"), told, "a device found when the tracker opens");
            lamp.setProperties(props("lamp", "hall"));
            lamp.setProperties(props("lamp", "hall")); // the same room again: nothing to tell
            ServiceRegistration<?> later = register("late", null); // no room: nothing to tell
            lamp.setProperties(props("lamp", null));
            later.setProperties(props("late", "bedroom"));
            later.unregister();
            assertEquals(java.util.List.of("lamp=opening", "lamp=hall", "lamp=-", "late=bedroom", "late=-"), told);
        }
    }

    /** Issue 29, item 4: closing (the owner stops) forgets every device at once, telling nobody device by device. */
    @Test
    void closingTellsNoRoomChangePerDevice() {
        for (int i = 0; i < 200; i++) {
            register("light-" + i, "room-" + i);
        }
        java.util.concurrent.atomic.AtomicInteger told = new java.util.concurrent.atomic.AtomicInteger();
        TrackedPlacements placements = new TrackedPlacements(context, uid -> told.incrementAndGet());
        assertEquals(200, told.get(), "each device placed when the tracker opens");
        placements.close();
        assertEquals(200, told.get(), "room changes told while closing over 200 devices");
        assertEquals(Optional.empty(), placements.roomOf("light-7"));
    }

    private ServiceRegistration<?> register(String uid, String room) {
        Device d = (Device) Proxy.newProxyInstance(Device.class.getClassLoader(), new Class<?>[] {Device.class},
                (proxy, method, args) -> switch (method.getName()) {
                    case "name" -> "Lamp " + uid;
                    case "hashCode" -> System.identityHashCode(proxy);
                    case "equals" -> proxy == args[0];
                    default -> null;
                });
        return context.registerService(Device.class, d, props(uid, room));
    }

    private ServiceRegistration<?> provider(String uid, String room) {
        return context.registerService(Runnable.class, () -> { }, props(uid, room));
    }

    private static Hashtable<String, Object> props(String uid, String room) {
        Hashtable<String, Object> p = new Hashtable<>();
        p.put(DeviceProperties.DEVICE_UID, uid);
        if (room != null) {
            p.put(DeviceProperties.ROOM, room);
        }
        return p;
    }
}
