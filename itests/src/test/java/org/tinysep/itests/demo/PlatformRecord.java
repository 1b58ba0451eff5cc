package org.tinysep.itests.demo;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.itests.Connections;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.Room;

/**
 * What the platform's services report while a simulation runs, as {@code "HH:mm:ss <what>"} in virtual time (UTC):
 * Flat Occupancy's changes, Inactivity Recognition's states, and every light's confirmations with its room. The
 * services appear only once the simulated nodes' devices do, so it connects to them whenever they come.
 */
final class PlatformRecord implements AutoCloseable {

    private static final DateTimeFormatter HMS = DateTimeFormatter.ofPattern("HH:mm:ss").withZone(ZoneOffset.UTC);

    final List<String> occupancy = new CopyOnWriteArrayList<>();
    final List<String> inactivity = new CopyOnWriteArrayList<>();
    /** {@code "HH:mm:ss <room> on|off"}; a room of {@code ?} when the device is not placed yet */
    final List<String> lights = new CopyOnWriteArrayList<>();
    private final Connections connections;

    PlatformRecord(BundleContext context, HouseInformationProvider house) {
        this.connections = new Connections(context);
        connections.to(FlatOccupancyProvider.class, (ref, p) -> p.connect((src, o, at) -> occupancy.add(hms(at) + " " + o)));
        connections.to(InactivityRecognitionProvider.class,
                (ref, p) -> p.connect((src, s, at) -> inactivity.add(hms(at) + " " + s)));
        connections.to(SimpleLightProvider.class, (ref, p) -> p.connect(
                (src, on, at) -> lights.add(hms(at) + " " + room(ref, house) + (on ? " on" : " off"))));
        connections.to(DimmableLightProvider.class, (ref, p) -> p.connect(
                (src, b, at) -> lights.add(hms(at) + " " + room(ref, house) + (b.value() > 0 ? " on" : " off"))));
    }

    /** @return the rooms of the lights' "on" confirmations, consecutive repeats merged */
    List<String> roomsLit() {
        List<String> rooms = new ArrayList<>();
        for (String l : lights) {
            if (l.endsWith(" on")) {
                String room = l.substring(9, l.length() - 3);
                if (rooms.isEmpty() || !rooms.get(rooms.size() - 1).equals(room)) {
                    rooms.add(room);
                }
            }
        }
        return rooms;
    }

    @Override
    public void close() {
        connections.close();
    }


    private static String room(ServiceReference<?> ref, HouseInformationProvider house) {
        Object uid = ref.getProperty(DeviceProperties.ROOM);
        return uid == null ? "?" : house.room(uid.toString()).map(Room::name).orElse("room " + uid);
    }

    private static String hms(Instant at) {
        return HMS.format(at);
    }

    @Override
    public String toString() {
        return "occupancy " + occupancy + ", inactivity " + inactivity + ", rooms lit " + roomsLit() + ", lights " + lights;
    }
}
