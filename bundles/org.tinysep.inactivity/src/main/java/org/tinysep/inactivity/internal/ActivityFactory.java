package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.Placements;

/**
 * Turns "device X reported something at T" into an {@link Activity}: the room from the device's
 * {@code tinysep.room} property at that moment, its name and type from House Information, its limit from the
 * {@link LimitTable}. A door's or window's first report is no activity ({@link ContactStates}).
 */
final class ActivityFactory implements MovementListener, DoorListener, WindowListener {

    private final Placements directory;
    private final LimitTable limits;
    private final Consumer<Activity> sink;
    private final ContactStates contacts = new ContactStates();
    private volatile Map<String, Room> rooms = Map.of();

    /** @param sink receives every activity: indoor motion, door and window changes (not their first reports) */
    ActivityFactory(Placements directory, LimitTable limits, Consumer<Activity> sink) {
        this.directory = directory;
        this.limits = limits;
        this.sink = sink;
    }

    /** A door or window was connected in state {@code current}. */
    void contactConnected(String deviceUid, OpenState current) {
        contacts.connected(deviceUid, current);
    }

    @Override
    public void movementReported(MovementProvider source, MovementEvent movement) {
        if (movement.detected() && source.location() == MovementLocation.INSIDE) {
            sink.accept(of(source.deviceUid(), n -> "movement by " + n, movement.at()));
        }
    }

    @Override
    public void doorChanged(DoorProvider source, OpenState state, Instant at) {
        if (contacts.isChange(source.deviceUid(), state)) {
            sink.accept(of(source.deviceUid(), n -> "door " + n + " " + lower(state), at));
        }
    }

    @Override
    public void windowChanged(WindowProvider source, OpenState state, Instant at) {
        if (contacts.isChange(source.deviceUid(), state)) {
            sink.accept(of(source.deviceUid(), n -> "window " + n + " " + lower(state), at));
        }
    }

    private static String lower(OpenState s) {
        return s.name().toLowerCase(Locale.ROOT);
    }

    /** The house plan changed (or became known). */
    void rooms(List<Room> plan) {
        rooms = plan.stream().collect(Collectors.toUnmodifiableMap(Room::uid, Function.identity(), (a, b) -> a));
    }

    /**
     * @param deviceUid the reporting device
     * @param what      builds the description from the device's name, e.g. {@code n -> "movement by " + n}
     */
    private Activity of(String deviceUid, Function<String, String> what, Instant at) {
        String name = directory.nameOf(deviceUid);
        String description = what.apply(name);
        Optional<String> roomUid = directory.roomOf(deviceUid);
        if (roomUid.isEmpty()) {
            return new Activity("", "unknown room (device " + name + ")", description, at, limits.defaultLimit());
        }
        Room room = rooms.get(roomUid.get());
        if (room == null) {
            return new Activity(roomUid.get(), "room " + roomUid.get(), description, at,
                    limits.limitForUnknownRoom(roomUid.get()));
        }
        return new Activity(room.uid(), room.name(), description, at, limits.limitFor(room));
    }

    int knownRooms() {
        return rooms.size();
    }
}
