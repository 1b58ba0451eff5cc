package org.tinysep.web.api.internal;

import java.time.Instant;
import java.time.ZoneId;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.health.UnmonitoredRoom;

/**
 * {@code GET /api/caregiver/sensors}: from the Sensor Health service ({@code org.tinysep.sensorhealth}, optional),
 * every sensor that is offline and every low battery, and the rooms nobody can watch now, each in plain words
 * ("the Bathroom has no working motion sensor since …: falls there cannot be noticed"). Without that service the
 * answer says so.
 */
final class SensorsApi {

    static final String NO_SERVICE = "no sensor health service: the Sensor Health bundle (org.tinysep.sensorhealth) "
            + "is not running, so nobody here can tell whether a sensor has stopped reporting or its battery is low";

    private final PlatformView platform;
    private final ZoneId zone;

    SensorsApi(PlatformView platform, ZoneId zone) {
        this.platform = platform;
        this.zone = zone;
    }

    Map<String, Object> status(Instant now) {
        Map<String, Object> out = platform.withService(SensorHealthProvider.class, this::report)
                .orElseGet(() -> {
                    Map<String, Object> m = new LinkedHashMap<>();
                    m.put("sensorHealth", false);
                    m.put("message", NO_SERVICE);
                    m.put("sensors", 0);
                    m.put("unmonitored", List.of());
                    m.put("offline", List.of());
                    m.put("lowBattery", List.of());
                    return m;
                });
        out.put("now", now);
        return out;
    }

    private Map<String, Object> report(SensorHealthProvider health) {
        List<SensorHealth> sensors = health.sensors();
        List<UnmonitoredRoom> rooms = health.unmonitoredRooms();
        Set<String> unmonitoredUids = rooms.stream().map(UnmonitoredRoom::roomUid).collect(Collectors.toSet());
        Map<String, SensorHealth> byDevice = new LinkedHashMap<>();
        sensors.forEach(s -> byDevice.put(s.node().deviceUid(), s));
        List<Object> unmonitored = new ArrayList<>();
        for (UnmonitoredRoom r : rooms) {
            String kinds = r.deviceUids().stream().map(byDevice::get).filter(s -> s != null)
                    .map(s -> SensorWords.kind(s.node().nodeTypes())).distinct().collect(Collectors.joining(" or "));
            String summary = "The " + r.roomName() + " has no working " + (kinds.isEmpty() ? "sensor" : kinds);
            String meaning = "a fall or a long stillness there cannot be noticed";
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("roomUid", r.roomUid());
            m.put("room", r.roomName());
            m.put("since", r.since());
            m.put("devices", r.deviceUids());
            m.put("summary", summary);
            m.put("meaning", meaning);
            m.put("text", summary + " since " + SensorWords.clock(r.since(), zone) + ": " + meaning + ".");
            unmonitored.add(m);
        }
        List<Object> offline = new ArrayList<>();
        List<Object> lowBattery = new ArrayList<>();
        for (SensorHealth s : sensors) {
            NodeHealth n = s.node();
            String what = "The " + SensorWords.kind(n.nodeTypes()) + " " + s.name() + " (node " + n.nodeAddress() + ")"
                    + (s.roomName() == null ? ", not placed in a room," : " in the " + s.roomName());
            if (!n.online()) {
                Instant since = n.silentSince() != null ? n.silentSince() : n.lastHeard();
                String summary = what + (since == null ? " has not been heard since the platform started"
                        : " has been silent");
                String meaning = SensorWords.meaning(n.nodeTypes(), s.roomName(),
                        s.roomUid() != null && unmonitoredUids.contains(s.roomUid()));
                Map<String, Object> m = entry(s);
                m.put("since", since);
                m.put("lastHeard", n.lastHeard());
                m.put("summary", summary);
                m.put("meaning", meaning);
                m.put("text", summary + (since == null ? "" : " since " + SensorWords.clock(since, zone)) + ": "
                        + meaning + ".");
                offline.add(m);
            }
            if (n.batteryLow()) {
                String summary = "The battery of the " + what.substring(4) + " is low"
                        + (n.batteryMillivolts() == null ? "" : " (" + n.batteryMillivolts() + " mV)");
                String meaning = "replace or recharge it soon, before the sensor stops reporting";
                Map<String, Object> m = entry(s);
                m.put("millivolts", n.batteryMillivolts());
                m.put("summary", summary);
                m.put("meaning", meaning);
                m.put("text", summary + ": " + meaning + ".");
                lowBattery.add(m);
            }
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("sensorHealth", true);
        out.put("message", unmonitored.isEmpty() && offline.isEmpty() && lowBattery.isEmpty()
                ? "All " + sensors.size() + " sensors report; no battery is low."
                : offline.size() + " of " + sensors.size() + " sensors offline, " + lowBattery.size()
                        + " with a low battery.");
        out.put("sensors", sensors.size());
        out.put("unmonitored", unmonitored);
        out.put("offline", offline);
        out.put("lowBattery", lowBattery);
        return out;
    }

    private static Map<String, Object> entry(SensorHealth s) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("deviceUid", s.node().deviceUid());
        m.put("name", s.name());
        m.put("kind", SensorWords.kind(s.node().nodeTypes()));
        m.put("nodeAddress", s.node().nodeAddress());
        m.put("roomUid", s.roomUid());
        m.put("room", s.roomName());
        return m;
    }
}
