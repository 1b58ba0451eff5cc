package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.BundleContext;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.device.support.testing.RealFelix;

/**
 * Issue 29, item 4: {@code tinysep:rooms} reads every placed device's name. A use given back with
 * {@code ungetService} stays in Felix's per-bundle use array (count 0) until the service goes, and every
 * unregistration scans those arrays: after one {@code rooms} over n devices, stopping them cost n². Counted in a
 * real Felix: the command leaves no use behind.
 */
class RoomsCommandUsesTest {

    @TempDir
    Path storage;
    private RealFelix fw;
    private BundleContext context;

    @BeforeEach
    void start() throws Exception {
        fw = new RealFelix(storage);
        context = fw.context();
    }

    @AfterEach
    void stop() throws Exception {
        fw.close();
    }


    private void device(int i, String room) {
        Device d = (Device) Proxy.newProxyInstance(getClass().getClassLoader(), new Class<?>[] {Device.class},
                (proxy, m, args) -> switch (m.getName()) {
                    case "name" -> "Sensor " + i;
                    case "hashCode" -> System.identityHashCode(proxy);
                    case "equals" -> proxy == args[0];
                    default -> null;
                });
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(DeviceProperties.DEVICE_UID, "dev-" + i);
        props.put(DeviceProperties.ROOM, room);
        context.registerService(Device.class, d, props);
    }

    @Test
    void theRoomsCommandLeavesNoUseBehind() throws Exception {
        int n = 400;
        for (int i = 0; i < n; i++) {
            device(i, i % 2 == 0 ? "kitchen" : "bath");
        }
        int base = fw.usesInRegistry();
        Map<String, List<String>> byRoom = ShellFunctions.devicesByRoom(context);
        assertEquals(n / 2, byRoom.get("kitchen").size());
        assertTrue(byRoom.get("bath").contains("Sensor 1"), byRoom.get("bath").toString());
        assertEquals(base, fw.usesInRegistry(), "uses left in the registry by reading " + n + " devices' names");
    }
}
