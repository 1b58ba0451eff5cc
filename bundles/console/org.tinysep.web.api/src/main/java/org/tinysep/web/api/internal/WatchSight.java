package org.tinysep.web.api.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.DeviceStatus;

/**
 * Whether the inactivity watch can see: its sensors are its vital connections (movement, door,
 * window, presence); it is <b>blind</b> when it has none or every one of them is OFFLINE (a sensor follows its
 * radio node), so the caregiver is not told "watching – someone is home" beside "25 of 25 sensors offline".
 *
 * @param sensors the sensors the watch listens to
 * @param offline the names of those OFFLINE now
 */
record WatchSight(int sensors, List<String> offline) {

    /**
     * @param connections the watch's connections ({@code Device.connections()})
     * @param statusOf    a device's status and name by UID; null for a device no longer registered
     */
    static WatchSight of(List<ConnectionInfo> connections, Function<String, Named> statusOf) {
        List<String> offline = new ArrayList<>();
        int sensors = 0;
        for (ConnectionInfo c : connections) {
            if (!c.vital()) {
                continue; // Flat Occupancy, the Mail Manager, House Information: not eyes
            }
            sensors++;
            Named n = statusOf.apply(c.providerDeviceUid());
            if (n == null || n.status().state() == DeviceStatus.State.OFFLINE) {
                offline.add(n == null ? c.providerDeviceUid() : n.name());
            }
        }
        return new WatchSight(sensors, List.copyOf(offline));
    }

    /** A device's name and status. */
    record Named(String name, DeviceStatus status) {
    }

    boolean blind() {
        return offline.size() == sensors;
    }

    /** @return the plain words of the watch's sight, for the caregiver */
    String words() {
        if (sensors == 0) {
            return "Blind: the inactivity watch has no sensor to listen to, so a fall cannot be noticed. Place a "
                    + "movement or door sensor in a room.";
        }
        if (blind()) {
            return "Blind: all " + sensors + " of its sensors are offline (" + String.join(", ", offline)
                    + "), so a fall cannot be noticed until one of them is heard again.";
        }
        return offline.isEmpty() ? "All " + sensors + " of its sensors report."
                : offline.size() + " of its " + sensors + " sensors offline (" + String.join(", ", offline) + ").";
    }

    Map<String, Object> json() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("blind", blind());
        m.put("sensors", sensors);
        m.put("sensorsOffline", offline.size());
        m.put("sight", words());
        return m;
    }
}
