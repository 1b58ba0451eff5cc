package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.Room;

/**
 * {@code GET /api/caregiver}: is the flat occupied, the inactivity state (and its alert), and per room the last
 * activity: the newest movement or door/window change reported by a sensor placed in that room within the last
 * {@value #DAYS} days (read from the event log's history; Inactivity Recognition's own state is the authority
 * for alerts).
 */
public final class CaregiverApi {

    static final int DAYS = 7;
    private static final Pattern ACTIVITY = Pattern.compile("movement detected|(door|window) (opened|closed)");

    private final PlatformView platform;

    public CaregiverApi(PlatformView platform) {
        this.platform = platform;
    }

    public Map<String, Object> status(EventLog log, Instant now) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("occupancy", platform.withService(FlatOccupancyProvider.class, f -> {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("state", f.occupancy());
            m.put("since", f.since());
            return m;
        }).orElse(null));
        out.put("inactivity", platform.withService(InactivityRecognitionProvider.class, r -> inactivity(r, platform))
                .orElse(null));
        Map<String, String> sensorRoom = sensorRooms(platform);
        Map<String, EventEntry> lastByRoom = new HashMap<>();
        if (!sensorRoom.isEmpty()) {
            List<EventEntry> entries = log.query(new LogQuery(now.minus(Duration.ofDays(DAYS)), null,
                    sensorRoom.keySet(), Set.of("DEVICE_EVENT"), 5000)).entries();
            for (EventEntry e : entries) { // oldest first: later ones overwrite
                String room = sensorRoom.get(e.origin());
                if (room != null && isActivity(e.message())) {
                    lastByRoom.put(room, e);
                }
            }
        }
        Map<String, String> names = platform.names();
        List<Object> rooms = new ArrayList<>();
        Map<String, Object> last = null;
        Instant lastAt = null;
        for (Room r : platform.withService(HouseInformationProvider.class, HouseInformationProvider::rooms).orElse(List.of())) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("uid", r.uid());
            m.put("name", r.name());
            m.put("type", r.type());
            EventEntry e = lastByRoom.get(r.uid());
            m.put("lastActivity", e == null ? null : activity(e, names, r));
            rooms.add(m);
            if (e != null && (lastAt == null || e.time().isAfter(lastAt))) {
                lastAt = e.time();
                last = activity(e, names, r);
            }
        }
        out.put("lastActivity", last);
        out.put("rooms", rooms);
        out.put("personNodes", PersonNodes.of(platform, now)); // wearer, last report, battery, worn, watch
        out.put("now", now);
        return out;
    }

    /** @return sensor UID → room UID of every movement, door and window sensor placed in a room */
    static Map<String, String> sensorRooms(PlatformView platform) {
        Map<String, String> sensorRoom = new HashMap<>();
        for (Class<?> type : List.of(MovementProvider.class, DoorProvider.class, WindowProvider.class)) {
            sensorRoom.putAll(platform.providersWithRoom(type));
        }
        return sensorRoom;
    }

    /** @return whether an event-log message of a sensor is activity (movement, a door or window opened or closed) */
    static boolean isActivity(String message) {
        return ACTIVITY.matcher(message).lookingAt();
    }

    private static Map<String, Object> activity(EventEntry e, Map<String, String> names, Room room) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("time", e.time());
        m.put("room", room.name());
        m.put("device", names.getOrDefault(e.origin(), e.origin()));
        m.put("message", e.message());
        return m;
    }

    /**
     * @return the watch's state, its alert, and whether it can see ({@link WatchSight}: {@code blind},
     *         {@code sensors}, {@code sensorsOffline}, {@code sight}) when the watch is a device
     */
    static Map<String, Object> inactivity(InactivityRecognitionProvider r, PlatformView platform) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("state", r.state());
        m.put("alert", r.alert().map(CaregiverApi::alert).orElse(null));
        if (r instanceof Device watch) {
            Map<String, WatchSight.Named> devices = new HashMap<>();
            for (PlatformView.DeviceRef d : platform.devices()) {
                DeviceStatus s = Safely.get(d.device()::status, null);
                devices.put(d.uid(), s == null ? null : new WatchSight.Named(Safely.get(() -> d.device().name(), d.uid()), s));
            }
            m.putAll(WatchSight.of(Safely.get(watch::connections, List.of()), devices::get).json());
        }
        return m;
    }

    private static Map<String, Object> alert(InactivityAlert a) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("room", a.roomName());
        m.put("lastActivity", a.lastActivity());
        m.put("lastActivityAt", a.lastActivityAt());
        m.put("raisedAt", a.raisedAt());
        return m;
    }
}
