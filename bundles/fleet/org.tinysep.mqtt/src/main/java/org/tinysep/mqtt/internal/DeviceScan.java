package org.tinysep.mqtt.internal;

import org.tinysep.device.support.lifecycle.Safely;
import static org.tinysep.json.JsonWriter.object;
import static org.tinysep.json.JsonWriter.writePlain;

import java.time.Instant;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.rooms.RoomDirectory;

/**
 * Reads every sensor's and actuator's state from its provider (every {@code pollSeconds}, on the bridge's thread)
 * and hands the state, availability, health and Home Assistant discovery messages to the outbox; the outbox only
 * sends what changed. A device providing several interfaces is published as the first of {@link DeviceKind}.
 */
final class DeviceScan implements AutoCloseable {

    private record Seen(Object value, Instant since) {
    }

    private final Topics topics;
    private final Discovery discovery;
    private final Supplier<Instant> clock;
    private final Map<DeviceKind, Tracked<Object>> providers = new EnumMap<>(DeviceKind.class);
    private final Tracked<Device> devices;
    private final Tracked<SensorHealthProvider> health;
    private final RoomDirectory rooms;
    private final Map<String, Seen> seen = new HashMap<>();
    private Set<String> present = new HashSet<>();
    private int offline;

    DeviceScan(BundleContext context, Topics topics, Supplier<Instant> clock) {
        this.topics = topics;
        this.discovery = new Discovery(topics);
        this.clock = clock;
        for (DeviceKind k : DeviceKind.values()) {
            providers.put(k, new Tracked<>(context, k.providerType));
        }
        this.devices = new Tracked<>(context, Device.class);
        this.health = new Tracked<>(context, SensorHealthProvider.class);
        this.rooms = RoomDirectory.tracking(context);
    }

    /** @return the kind and provider of a device, for commands; null when it is not published */
    Map.Entry<DeviceKind, Object> find(String uid) {
        for (DeviceKind k : DeviceKind.values()) {
            Tracked.Entry<Object> e = providers.get(k).get(uid);
            if (e != null) {
                return Map.entry(k, e.service());
            }
        }
        return null;
    }

    Device device(String uid) {
        Tracked.Entry<Device> e = devices.get(uid);
        return e == null ? null : e.service();
    }

    void poll(Consumer<Message> out) {
        Map<String, NodeHealth> nodes = nodes();
        Map<String, DeviceKind> now = new LinkedHashMap<>();
        offline = 0;
        for (DeviceKind k : DeviceKind.values()) {
            for (String uid : providers.get(k).all().keySet()) {
                now.putIfAbsent(uid, k);
            }
        }
        for (Map.Entry<String, DeviceKind> e : now.entrySet()) {
            publish(e.getKey(), e.getValue(), nodes, out);
        }
        for (String gone : present) {
            if (!now.containsKey(gone)) {
                out.accept(Message.state(topics.deviceAvailability(gone), "offline"));
                seen.remove(gone);
            }
        }
        present = now.keySet();
    }

    private void publish(String uid, DeviceKind kind, Map<String, NodeHealth> nodes, Consumer<Message> out) {
        Tracked.Entry<Object> p = providers.get(kind).get(uid);
        if (p == null) {
            return;
        }
        Tracked.Entry<Device> d = devices.get(uid);
        Object value = Safely.get(() -> kind.value(p.service()), null);
        Instant at = clock.get();
        Seen before = seen.get(uid);
        if (before == null || !Objects.equals(before.value, value)) {
            before = new Seen(value, at);
            seen.put(uid, before);
        }
        String name = d == null ? uid : Safely.get(() -> d.service().name(), uid);
        Object roomUid = (d == null ? p.ref() : d.ref()).getProperty(DeviceProperties.ROOM);
        String room = roomUid == null ? "" : rooms.room(roomUid.toString()).map(Room::name).orElse(roomUid.toString());
        String where = name + (room.isEmpty() ? "" : " (" + room + ")");
        out.accept(Message.state(topics.deviceState(uid), writePlain(object("uid", uid, "name", name,
                "room", room, "type", kind.type, "value", value, "since", before.since,
                "explanation", where + ": " + kind.describe(value)))));
        DeviceStatus status = d == null ? null : Safely.get(() -> d.service().status(), null);
        Object address = (d == null ? p.ref() : d.ref()).getProperty(DeviceProperties.NODE_ADDRESS);
        NodeHealth node = address == null ? null : nodes.get(address.toString());
        boolean online = (status == null || status.state() == DeviceStatus.State.ONLINE
                || status.state() == DeviceStatus.State.UNKNOWN) && (node == null || node.online());
        if (!online) {
            offline++;
        }
        out.accept(Message.state(topics.deviceAvailability(uid), online ? "online" : "offline"));
        out.accept(Message.state(topics.deviceHealth(uid), writePlain(object(
                "status", status == null ? "UNKNOWN" : status.state().name(),
                "battery", null,
                "batteryMillivolts", node == null ? null : node.batteryMillivolts(),
                "batteryLow", node != null && node.batteryLow(),
                "lastReport", node == null ? null : node.lastHeard(),
                "linkQuality", node == null || node.linkQualityPercent() < 0 ? null : node.linkQualityPercent(),
                "explanation", HealthText.explain(where, status, node)))));
        if (topics.discovery()) {
            out.accept(discovery.device(uid, kind, name, room));
            if (node != null && node.batteryMillivolts() != null) {
                out.accept(discovery.battery(uid));
            }
        }
    }

    private Map<String, NodeHealth> nodes() {
        Map<String, NodeHealth> byAddress = new HashMap<>();
        for (Tracked.Entry<SensorHealthProvider> e : health.all().values()) {
            List<SensorHealth> all = Safely.get(() -> e.service().sensors(), List.of());
            for (SensorHealth s : all) {
                byAddress.put(s.node().nodeAddress(), s.node());
            }
        }
        return byAddress;
    }

    int devices() {
        return present.size();
    }

    int offline() {
        return offline;
    }

    @Override
    public void close() {
        providers.values().forEach(Tracked::close);
        devices.close();
        health.close();
        rooms.close();
    }
}
