package org.tinysep.sensorhealth.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.UnmonitoredRoom;

/**
 * Rooms none of whose sensing nodes can be heard. A sensing node watches the person: a movement, door or window
 * sensor (a light or heater reports its own state, a pet collar moves with the pet, a temperature sensor sees no
 * one). A room without any placed sensing node is not "unmonitored": it never was monitored.
 */
final class Unmonitored {

    static final Set<String> SENSING = Set.of(NodeType.MOVEMENT, NodeType.DOOR, NodeType.WINDOW);

    private Unmonitored() {
    }

    static boolean sensing(SensorHealth s) {
        return s.node().nodeTypes().stream().anyMatch(SENSING::contains);
    }

    /** @return the unmonitored rooms among the sensors' rooms, by room name */
    static List<UnmonitoredRoom> of(List<SensorHealth> sensors) {
        Map<String, List<SensorHealth>> byRoom = new LinkedHashMap<>();
        for (SensorHealth s : sensors) {
            if (s.roomUid() != null && sensing(s)) {
                byRoom.computeIfAbsent(s.roomUid(), r -> new ArrayList<>()).add(s);
            }
        }
        List<UnmonitoredRoom> out = new ArrayList<>();
        byRoom.forEach((room, inRoom) -> {
            if (inRoom.stream().noneMatch(s -> s.node().online())) {
                Instant since = inRoom.stream().map(s -> s.node().silentSince() != null ? s.node().silentSince()
                        : s.node().lastHeard()).filter(t -> t != null).max(Comparator.naturalOrder())
                        .orElse(Instant.EPOCH);
                out.add(new UnmonitoredRoom(room, inRoom.get(0).roomName() == null ? room : inRoom.get(0).roomName(),
                        since, inRoom.stream().map(s -> s.node().deviceUid()).toList()));
            }
        });
        out.sort(Comparator.comparing(UnmonitoredRoom::roomName));
        return out;
    }
}
