package org.tinysep.sensorhealth.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.RoomDirectory;

/**
 * Every node's health with where it is: the bus devices' {@link NodeHealthSource}s, placed by their own room or,
 * more often, by the room of the device above them (the movement sensor the user put in the Bathroom is connected
 * to the node's bus device), named by that device. Reads the service registry on each call.
 */
final class NodeView implements AutoCloseable {

    private final ServiceTracker<NodeHealthSource, NodeHealthSource> sources;
    private final ServiceTracker<Device, Device> devices;
    private final RoomDirectory rooms;

    NodeView(BundleContext context, RoomDirectory rooms) {
        this.rooms = rooms;
        this.sources = new ServiceTracker<>(context, NodeHealthSource.class, null);
        try {
            this.devices = new ServiceTracker<>(context, FrameworkUtil.createFilter("(&(objectClass="
                    + Device.class.getName() + ")(" + DeviceProperties.NODE_ADDRESS + "=*))"), null);
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        sources.open();
        devices.open();
    }

    /** A device on a node: its service properties and the device. */
    private record OnNode(String uid, String room, Device device) {
    }

    /** @return every node's health, by room name then node address */
    List<SensorHealth> sensors() {
        Map<String, List<OnNode>> byAddress = new HashMap<>();
        Map<String, OnNode> byUid = new HashMap<>();
        devices.getTracked().forEach((ref, device) -> {
            OnNode d = new OnNode(String.valueOf(ref.getProperty(DeviceProperties.DEVICE_UID)),
                    (String) ref.getProperty(DeviceProperties.ROOM), device);
            byUid.put(d.uid(), d);
            byAddress.computeIfAbsent(String.valueOf(ref.getProperty(DeviceProperties.NODE_ADDRESS)),
                    a -> new ArrayList<>()).add(d);
        });
        List<SensorHealth> out = new ArrayList<>();
        sources.getTracked().forEach((ref, source) -> {
            NodeHealth h;
            try {
                h = source.health();
            } catch (RuntimeException e) { // a bus device being removed: skip it this time
                return;
            }
            OnNode bus = byUid.get(h.deviceUid());
            String room = (String) ref.getProperty(DeviceProperties.ROOM);
            String name = bus == null ? "node " + h.nodeAddress() : bus.device().name();
            for (OnNode above : byAddress.getOrDefault(h.nodeAddress(), List.of())) {
                if (!above.uid().equals(h.deviceUid()) && connectedTo(above.device(), h.deviceUid())) {
                    name = above.device().name();
                    if (room == null && above.room() != null) {
                        room = above.room();
                    }
                    if (above.room() != null) {
                        break;
                    }
                }
            }
            String roomUid = room;
            String roomName = room == null ? null : rooms.room(room).map(Room::name).orElse(room);
            out.add(new SensorHealth(h, name, roomUid, roomName));
        });
        out.sort(Comparator.comparing((SensorHealth s) -> s.roomName() == null ? "\uffff" : s.roomName())
                .thenComparing(s -> s.node().nodeAddress()));
        return out;
    }

    private static boolean connectedTo(Device device, String busUid) {
        try {
            return device.connections().stream().anyMatch(c -> Objects.equals(c.providerDeviceUid(), busUid));
        } catch (RuntimeException e) {
            return false;
        }
    }

    @Override
    public void close() {
        sources.close();
        devices.close();
    }
}
