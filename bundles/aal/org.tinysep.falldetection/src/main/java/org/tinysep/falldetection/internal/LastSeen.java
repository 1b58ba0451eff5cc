package org.tinysep.falldetection.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.rooms.Placements;

/**
 * Where the person was last seen, for the FALL alert's words: the room of the newest activity the room sensors
 * reported (motion INSIDE, a door opened or closed, a mat, seat or appliance turning on or off). A report only notes
 * the device, the time and the words; the room (the device's {@code tinysep.room}) and its name from House
 * Information are looked up when a fall alert asks ({@link #last()}), as Inactivity Recognition finds them: motion
 * reports come on the radio's delivery thread many times a second, a fall alert seldom (looking the room and the
 * device's name up per report was a third of that thread's time at 50k frames/s). First reports after a start (a
 * door's resting state) are no sighting. The room sensors see anyone, so in a flat with two people this is where
 * someone was last seen.
 */
final class LastSeen implements MovementListener, DoorListener, PresenceListener {

    /** A sighting: the room's name for people, when, and by what (e.g. "its motion sensor"). */
    record Sighting(String room, Instant at, String by) {
    }

    private final Placements directory;
    private volatile Map<String, Room> rooms = Map.of();
    /** The newest report, as noted: the room is looked up when asked. */
    private record Noted(String deviceUid, Instant at, String by) {
    }

    private volatile Noted last;

    LastSeen(Placements directory) {
        this.directory = directory;
    }

    /** @return the newest sighting, empty when no room sensor has reported activity since the start */
    Optional<Sighting> last() {
        Noted n = last;
        return n == null ? Optional.empty() : Optional.of(new Sighting(room(n.deviceUid()), n.at(), n.by()));
    }

    /** The house plan changed (or became known). */
    void rooms(List<Room> plan) {
        rooms = plan.stream().collect(Collectors.toUnmodifiableMap(Room::uid, Function.identity(), (a, b) -> a));
    }

    @Override
    public void movementReported(MovementProvider source, MovementEvent movement) {
        if (movement.detected() && source.location() == MovementLocation.INSIDE) {
            seen(source.deviceUid(), movement.at(), "its motion sensor");
        }
    }

    @Override
    public void doorChanged(DoorProvider source, OpenState state, boolean first, Instant at) {
        if (!first && state != OpenState.UNKNOWN) {
            seen(source.deviceUid(), at, "its door sensor (door " + state.name().toLowerCase(Locale.ROOT) + ")");
        }
    }

    @Override
    public void doorChanged(DoorProvider source, OpenState state, Instant at) {
        doorChanged(source, state, false, at);
    }

    @Override
    public void presenceChanged(PresenceProvider source, boolean present, boolean first, Instant at) {
        if (!first) {
            seen(source.deviceUid(), at, "its " + source.kind().name().toLowerCase(Locale.ROOT) + " sensor ("
                    + (present ? "on" : "off") + ")");
        }
    }

    private synchronized void seen(String deviceUid, Instant at, String by) {
        Noted before = last;
        if (before != null && at.isBefore(before.at())) {
            return; // a late report does not move the person back
        }
        last = new Noted(deviceUid, at, by);
    }

    /** @return the room's name, "room &lt;uid&gt;" when House Information does not know it, or the device's words */
    private String room(String deviceUid) {
        Optional<String> uid = directory.roomOf(deviceUid);
        if (uid.isEmpty()) {
            return "an unknown room (device " + directory.nameOf(deviceUid) + " is not placed in a room)";
        }
        Room r = rooms.get(uid.get());
        return r == null ? "room " + uid.get() : "the " + r.name();
    }
}
