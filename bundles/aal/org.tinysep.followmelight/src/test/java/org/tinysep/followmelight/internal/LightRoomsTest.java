package org.tinysep.followmelight.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.ServiceRegistration;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.testing.RealFelix;

/**
 * In a real Felix registry: a light's room follows the {@code tinysep.room} property of its light service as it is
 * registered, changed (the user moved it; its room left the plan) and unregistered, and each change is told, so the
 * lights-by-room index is filed anew. Services that are not lights are not watched.
 */
class LightRoomsTest {

    @TempDir
    Path storage;
    private RealFelix fw;
    private final List<String> told = new ArrayList<>();

    @BeforeEach
    void start() throws Exception {
        fw = new RealFelix(storage);
    }

    @AfterEach
    void stop() throws Exception {
        fw.close();
    }

    private static Hashtable<String, Object> props(String uid, String room) {
        Hashtable<String, Object> p = new Hashtable<>();
        p.put(DeviceProperties.DEVICE_UID, uid);
        if (room != null) {
            p.put(DeviceProperties.ROOM, room);
        }
        return p;
    }

    @Test
    void aLightsRoomFollowsItsServiceProperty() {
        ServiceRegistration<SimpleLightProvider> lamp = fw.context().registerService(SimpleLightProvider.class,
                new QuietLight("lamp"), props("lamp", "r1"));
        try (LightRooms rooms = new LightRooms(fw.context(), new FakePlacements(), told::add)) {
            assertEquals(Optional.of("r1"), rooms.roomOf("lamp"), "a light there before");
            lamp.setProperties(props("lamp", "r2"));
            assertEquals(Optional.of("r2"), rooms.roomOf("lamp"), "moved");
            lamp.setProperties(props("lamp", null));
            assertEquals(Optional.empty(), rooms.roomOf("lamp"), "its room left the plan");
            ServiceRegistration<SimpleLightProvider> spot = fw.context().registerService(SimpleLightProvider.class,
                    new QuietLight("spot"), props("spot", "r3"));
            assertEquals(Optional.of("r3"), rooms.roomOf("spot"), "a light that came later");
            spot.unregister();
            assertEquals(Optional.empty(), rooms.roomOf("spot"), "a light that went");
            fw.context().registerService(MovementProvider.class, new Fakes.Movement("sensor"), props("sensor", "r1"));
            assertEquals(Optional.empty(), rooms.roomOf("sensor"), "not a light");
            assertEquals(List.of("lamp", "lamp", "lamp", "spot", "spot"), told);
        }
        lamp.unregister();
    }
}
