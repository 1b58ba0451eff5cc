package org.tinysep.itests.demo;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Pattern;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.Room;
import org.tinysep.itests.Connections;

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
    /** A light's "on" request in the event log: {@code light on requested}, {@code brightness 100% requested}. */
    private static final Pattern ON_REQUEST = Pattern.compile("light on requested|brightness [1-9][0-9]*% requested");

    private final Connections connections;
    private final BundleContext context;

    PlatformRecord(BundleContext context, HouseInformationProvider house) {
        this.connections = new Connections(context);
        this.context = context;
        connections.to(FlatOccupancyProvider.class, (ref, p) -> p.connect((src, o, at) -> occupancy.add(hms(at) + " " + o)));
        connections.to(InactivityRecognitionProvider.class,
                (ref, p) -> p.connect((src, s, at) -> inactivity.add(hms(at) + " " + s)));
        connections.to(SimpleLightProvider.class, (ref, p) -> p.connect(
                (src, on, at) -> lights.add(hms(at) + " " + room(ref, house) + (on ? " on" : " off"))));
        connections.to(DimmableLightProvider.class, (ref, p) -> p.connect(
                (src, b, at) -> lights.add(hms(at) + " " + room(ref, house) + (b.value() > 0 ? " on" : " off"))));
    }

    /**
     * @return the rooms whose lights were asked to go on, in the order of the requests, consecutive repeats merged.
     *         Requests are made on the thread that delivers the motion report, so their order follows the lock-step
     *         virtual time; the confirmations come back through the lights' command executors and may cross.
     */
    List<String> roomsRequested(EventLog log, HouseInformationProvider house) throws InvalidSyntaxException {
        List<String> rooms = new ArrayList<>();
        for (EventEntry e : log.recent(Integer.MAX_VALUE)) {
            if (e.kind() != EventKind.DEVICE_EVENT || !ON_REQUEST.matcher(e.message()).matches()) {
                continue;
            }
            ServiceReference<?>[] refs = context.getServiceReferences((String) null,
                    "(" + DeviceProperties.DEVICE_UID + "=" + e.origin() + ")");
            String room = refs == null ? "device " + e.origin() + " gone" : room(refs[0], house);
            if (rooms.isEmpty() || !rooms.get(rooms.size() - 1).equals(room)) {
                rooms.add(room);
            }
        }
        return rooms;
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
