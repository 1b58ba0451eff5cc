package org.tinysep.followmelight.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;
import org.tinysep.device.support.rooms.Placements;

/**
 * The one Follow Me Light device (thesis 4.4.4.2). Lights (simple and dimmable) are its vital connections;
 * movement, pet movement, Flat Occupancy and House Information are optional. It provides no interface.
 */
final class FollowMeDevice extends WholeFlatDevice implements MovementListener {

    private final Placements directory;
    private final FollowMeLogic logic;
    private final Lights lights;
    private final Duration grace;
    private final Set<String> unplacedReported = ConcurrentHashMap.newKeySet();
    private volatile Consumer<Instant> due = at -> { };
    private volatile Map<String, Room> rooms = Map.of();
    private volatile String occupancySource;

    /**
     * @param directory where sensors are (read per report), where lights are (read when a light is connected or
     *                  {@link #lightMoved moved}) and what devices are called
     */
    FollowMeDevice(DriverContext context, Placements directory, Duration grace, Percent brightness) {
        super(context, Uids.of(context.driverName(), "follow-me"), context.driverName(), "Follow me light");
        this.directory = directory;
        this.grace = grace;
        this.logic = new FollowMeLogic(grace);
        this.lights = new Lights(directory, brightness);
        status(DeviceStatus.State.ONLINE, "");
    }

    void control(SimpleLightProvider p) {
        lights.add(p);
        connect(p, SimpleLightProvider.class, (src, on, at) -> {
            if (!on) {
                lights.reportedOff(src.deviceUid());
            }
        }, true);
    }

    void control(DimmableLightProvider p) {
        lights.add(p);
        connect(p, DimmableLightProvider.class, (src, b, at) -> {
            if (b.value() == 0) {
                lights.reportedOff(src.deviceUid());
            }
        }, true);
    }

    void use(MovementProvider p) {
        connect(p, MovementProvider.class, this, false);
    }

    void use(PetMovementProvider p) {
        connect(p, PetMovementProvider.class, (src, m) -> {
            if (m.detected()) {
                inRoomOf(src.deviceUid(), m.at(), true);
            }
        }, false);
    }

    void use(FlatOccupancyProvider p) {
        occupancySource = p.deviceUid();
        connect(p, FlatOccupancyProvider.class, (src, o, at) -> occupancy(o, at), false);
        occupancy(p.occupancy(), p.since());
    }

    void use(HouseInformationProvider p) {
        connect(p, HouseInformationProvider.class, (src, plan, at) -> rooms(plan), false);
        rooms(p.rooms());
    }

    /** The placement of device {@code uid} changed (the driver's {@code TrackedPlacements} says so). */
    void lightMoved(String uid) {
        lights.moved(uid);
    }

    /** A provider went away (the driver closes the connection). */
    void forget(String providerUid) {
        lights.forget(providerUid);
        if (providerUid.equals(occupancySource)) {
            occupancySource = null;
            occupancy(Occupancy.UNKNOWN, now());
        }
    }

    @Override
    public void movementReported(MovementProvider source, MovementEvent movement) {
        if (movement.detected() && source.location() == MovementLocation.INSIDE) {
            inRoomOf(source.deviceUid(), movement.at(), false);
        }
    }

    private void inRoomOf(String sensorUid, Instant at, boolean pet) {
        String room = directory.roomOf(sensorUid).orElse(null);
        if (room == null) {
            if (unplacedReported.add(sensorUid)) {
                event("motion from " + directory.nameOf(sensorUid) + " ignored: the device is not placed in a room");
            }
            return;
        }
        if (!unplacedReported.isEmpty()) {
            unplacedReported.remove(sensorUid); // placed now: a later unplacing is reported again
        }
        synchronized (logic) {
            apply(pet ? logic.petMotion(room, at) : logic.personMotion(room, at));
        }
    }

    private void occupancy(Occupancy o, Instant at) {
        synchronized (logic) {
            apply(logic.occupancy(o, at));
            if (o != Occupancy.OCCUPIED) {
                List<String> off = lights.offAll();
                if (!off.isEmpty()) {
                    event("switched off " + String.join(", ", off) + " (flat " + o.name().toLowerCase() + ")");
                }
            }
        }
    }

    /**
     * Advances the algorithm's clock; called by the driver's ticker when due.
     *
     * @return when it is next due: the end of the first lit room's grace period, null while no room is lit
     */
    Instant tick(Instant now) {
        synchronized (logic) {
            apply(logic.tick(now));
            return logic.nextDue();
        }
    }

    /** Where the device says that a room was lit: its grace period needs a tick when it ends (the driver's ticker). */
    void whenDue(Consumer<Instant> due) {
        this.due = due;
    }

    private void apply(List<Command> commands) {
        if (commands.isEmpty()) {
            return; // most reports: the room is lit already
        }
        if (commands.stream().anyMatch(Command::on)) {
            due.accept(logic.nextDue()); // a room lit now: its grace period ends later
        }
        for (Command c : commands) {
            List<String> switched = c.on() ? lights.on(c.roomUid()) : lights.off(c.roomUid());
            event(roomName(c.roomUid()) + (c.on() ? " lit" : " dark") + " (" + c.reason() + ")"
                    + (switched.isEmpty() ? "" : ": " + (c.on() ? "on " : "off ") + String.join(", ", switched)));
        }
    }

    private void rooms(List<Room> plan) {
        rooms = plan.stream().collect(Collectors.toUnmodifiableMap(Room::uid, Function.identity(), (a, b) -> a));
        lights.movedAll(); // a room removed from the house unplaces its lights
    }

    private String roomName(String uid) {
        Room r = rooms.get(uid);
        return r == null ? "room " + uid : r.name();
    }

    @Override
    protected List<Parameter> moreParameters() {
        synchronized (logic) {
            return List.of(
                    Parameter.readOnly("occupancy", logic.occupancy(), "as last heard from Flat Occupancy"),
                    Parameter.readOnly("litRooms", logic.litRooms().stream().map(this::roomName).sorted()
                            .collect(Collectors.joining(", ")), "rooms this service keeps lit"),
                    Parameter.readOnly("switchedOn", lights.ours().size(), "lights this service switched on"),
                    Parameter.readOnly("lights", lights.count(), "lights connected"),
                    Parameter.readOnly("graceSeconds", grace.toSeconds(),
                            "configured in pid org.tinysep.followmelight"));
        }
    }
}
