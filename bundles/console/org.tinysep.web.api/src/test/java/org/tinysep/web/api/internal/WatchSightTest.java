package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.DeviceStatus;

/** The inactivity watch is "blind" when every sensor it listens to is offline (issue 32, item 3). */
class WatchSightTest {

    private static final Instant T = Instant.parse("2026-11-29T03:00:00Z");

    private final Map<String, WatchSight.Named> devices = new HashMap<>();
    private final List<ConnectionInfo> connections = List.of(
            new ConnectionInfo("MovementProvider", "m1", true), new ConnectionInfo("DoorProvider", "d1", true),
            new ConnectionInfo("FlatOccupancyProvider", "occ", false));

    private void device(String uid, String name, DeviceStatus.State state) {
        devices.put(uid, new WatchSight.Named(name, new DeviceStatus(state, "", T)));
    }

    @Test
    void blindOnlyWhenEveryVitalSensorIsOffline() {
        device("m1", "Kitchen motion", DeviceStatus.State.OFFLINE);
        device("d1", "Front door", DeviceStatus.State.ONLINE);
        device("occ", "Flat occupancy", DeviceStatus.State.OFFLINE); // not a sensor: optional connection
        WatchSight some = WatchSight.of(connections, devices::get);
        assertFalse(some.blind());
        assertEquals("1 of its 2 sensors offline (Kitchen motion).", some.words());

        device("d1", "Front door", DeviceStatus.State.OFFLINE);
        WatchSight all = WatchSight.of(connections, devices::get);
        assertTrue(all.blind());
        assertEquals("Blind: all 2 of its sensors are offline (Kitchen motion, Front door), so a fall cannot be "
                + "noticed until one of them is heard again.", all.words());
        assertEquals(Map.of("blind", true, "sensors", 2, "sensorsOffline", 2, "sight", all.words()), all.json());
    }

    @Test
    void anUnknownStateIsNotOfflineAndAVanishedSensorIs() {
        device("m1", "Kitchen motion", DeviceStatus.State.UNKNOWN); // just started, no report yet
        WatchSight s = WatchSight.of(connections, devices::get); // d1 is no longer registered
        assertFalse(s.blind());
        assertEquals(List.of("d1"), s.offline());
    }

    @Test
    void aWatchWithoutSensorsIsBlind() {
        WatchSight none = WatchSight.of(List.of(new ConnectionInfo("MailManagerProvider", "mail", false)),
                devices::get);
        assertTrue(none.blind());
        assertTrue(none.words().startsWith("Blind: the inactivity watch has no sensor"), none.words());
    }
}
