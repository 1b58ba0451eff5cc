package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Sighting;
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
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.device.support.rooms.Placements;

/**
 * Turns "device X reported something at T" into an {@link Activity}: the room from the device's
 * {@code tinysep.room} property at that moment, its name and type from House Information, its limit from the
 * {@link LimitTable}. A door's or window's first report after its device started only tells its state: it is no
 * activity (the device says so: {@code first}, sensor API 1.1). Counting it would make every restart look like
 * activity in every room with a door or window, and would move an unanswered alert's clock to another room.
 */
final class ActivityFactory implements MovementListener, DoorListener, WindowListener, PresenceListener {

    private final Placements directory;
    private final LimitTable limits;
    private final LimitPolicy policy;
    private final Supplier<Instant> clock;
    private final Sink sink;
    private volatile Map<String, Room> rooms = Map.of();
    private final UnplacedNames unplaced;
    /** The room (UID, empty if unplaced) of the last activity, null before the first. */
    private volatile String lastRoom;
    /** Each reporting device's room as of its last report (see {@link #spot}). */
    private final Map<String, Spot> spots = new ConcurrentHashMap<>();
    /** More reporting devices than a home has: start the spots afresh (bounded memory). */
    static final int MAX_SPOTS = 4_096;

    /**
     * Receives every activity with the platform's time it was made at: the clock is read once per report, for the
     * limit (the learner's day) and for the detector (issue 29, item 1: the platform's time was asked twice per
     * movement report, each time through the Time Controller's lock).
     */
    @FunctionalInterface
    interface Sink {
        void accept(Activity activity, Instant now);
    }

    /** @param sink receives every activity: indoor motion, door and window changes (not their first reports) */
    ActivityFactory(Placements directory, LimitTable limits, Consumer<Activity> sink) {
        this(directory, limits, LimitPolicy.thesis(), Instant::now, (a, now) -> sink.accept(a));
    }

    /**
     * @param policy sets each activity's limit (fixed or learned) from the room's fixed limit
     * @param clock  the platform's time, read once per activity
     */
    ActivityFactory(Placements directory, LimitTable limits, LimitPolicy policy, Supplier<Instant> clock,
            Sink sink) {
        this.directory = directory;
        this.limits = limits;
        this.policy = policy;
        this.clock = clock;
        this.sink = sink;
        this.unplaced = new UnplacedNames(directory);
    }

    @Override
    public void movementReported(MovementProvider source, MovementEvent movement) {
        if (movement.detected() && source.location() == MovementLocation.INSIDE) {
            Spot s = spot(source.deviceUid());
            emit(s.placed(), s.movement(), movement.at(), false, false, false);
        }
    }

    @Override
    public void doorChanged(DoorProvider source, OpenState state, boolean first, Instant at) {
        if (!first && state != OpenState.UNKNOWN) {
            emit(source.deviceUid(), n -> "door " + n + " " + lower(state), at);
        }
    }

    /** A caller of the sensor API 1.0 call reports a change. */
    @Override
    public void doorChanged(DoorProvider source, OpenState state, Instant at) {
        doorChanged(source, state, false, at);
    }

    @Override
    public void windowChanged(WindowProvider source, OpenState state, boolean first, Instant at) {
        if (!first && state != OpenState.UNKNOWN) {
            emit(source.deviceUid(), n -> "window " + n + " " + lower(state), at);
        }
    }

    /** A caller of the sensor API 1.0 call reports a change. */
    @Override
    public void windowChanged(WindowProvider source, OpenState state, Instant at) {
        windowChanged(source, state, false, at);
    }

    /** A mat, flush or appliance turning on or off is activity; a bed mat turning on says the person is in bed. */
    @Override
    public void presenceChanged(PresenceProvider source, boolean present, boolean first, Instant at) {
        Placed p = spot(source.deviceUid()).placed();
        if (source.kind() == PresenceKind.BED || source.kind() == PresenceKind.SEAT) {
            policy.mat(source.deviceUid(), p.uid(), source.kind() == PresenceKind.BED, present);
        }
        if (first) {
            return; // the resting state after a start, like a contact's first report
        }
        String what = source.kind().name().toLowerCase(Locale.ROOT);
        boolean inBed = present && source.kind() == PresenceKind.BED;
        boolean seated = present && source.kind() == PresenceKind.SEAT;
        boolean up = !present && source.kind() == PresenceKind.BED;
        if (finishedByItself(source.kind(), present, p.uid(), lastRoom)) {
            return;
        }
        emit(p, source.deviceUid(), n -> what + " " + n + (present ? " on" : " off"), at, inBed, seated, up);
    }

    /**
     * A flush or an appliance turning OFF while the last activity was in another room is the device finishing by
     * itself (the cistern full, the kettle done), not the person: they were last seen elsewhere. Counting it would
     * start the quiet period in the device's room with that room's limit (a night flush that ends 18 s after the
     * person lay down in bed would be watched with the bathroom's 20 min instead of the night's).
     *
     * @param lastRoom the room of the last activity, null before the first
     */
    static boolean finishedByItself(PresenceKind kind, boolean present, String room, String lastRoom) {
        return !present && (kind == PresenceKind.FLUSH || kind == PresenceKind.APPLIANCE) && lastRoom != null
                && !lastRoom.equals(room);
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
    private void emit(String deviceUid, Function<String, String> what, Instant at) {
        emit(spot(deviceUid).placed(), deviceUid, what, at, false, false, false);
    }

    private void emit(Placed p, String deviceUid, Function<String, String> what, Instant at, boolean inBed,
            boolean seated, boolean upFromBed) {
        // the device's name is a registry look-up: made when the description is read, not per activity
        emit(p, () -> what.apply(directory.nameOf(deviceUid)), at, inBed, seated, upFromBed);
    }

    /** Makes the activity (its limit from the policy) and hands it on, with the platform's time read once. */
    private void emit(Placed p, Supplier<String> describe, Instant at, boolean inBed, boolean seated,
            boolean upFromBed) {
        if (!p.uid().equals(lastRoom)) {
            lastRoom = p.uid(); // a volatile write (a fence) only when the room changes, not per report
        }
        Instant now = clock.get();
        Limit l = policy.limitAfter(new Sighting(at, p.uid(), p.name(), p.type(), inBed, seated, upFromBed), p.fixed(),
                now);
        sink.accept(Activity.described(p.uid(), p.name(), describe, at, l.limit(), l.explanation()), now);
    }

    /**
     * A device's room as found at its last report, with the words of its movement (built when read): reused while
     * its room ({@link Placements#roomOf}, a map read), the house plan and, without a room, its looked-up name are
     * the same, so a report does not find the room's limit anew (issue 29, item 1: the limit table's look-up and
     * the new {@link Placed} per report were a tenth of what a movement report allocated).
     */
    private record Spot(Optional<String> roomUid, Map<String, Room> plan, Placed placed, Supplier<String> movement) {
    }

    private Spot spot(String deviceUid) {
        Optional<String> roomUid = directory.roomOf(deviceUid);
        Map<String, Room> plan = rooms;
        Spot s = spots.get(deviceUid);
        if (s != null && s.plan() == plan && s.roomUid().equals(roomUid)
                && (roomUid.isPresent() || s.placed().name().equals(unplaced.nameOf(deviceUid)))) {
            return s;
        }
        s = new Spot(roomUid, plan, placed(deviceUid, roomUid, plan),
                () -> "movement by " + directory.nameOf(deviceUid));
        if (spots.size() >= MAX_SPOTS) {
            spots.clear();
        }
        spots.put(deviceUid, s);
        return s;
    }

    /** A device's room now: UID (empty if unplaced), name, type and fixed limit. */
    record Placed(String uid, String name, String type, Duration fixed) {
    }

    Placed placed(String deviceUid) {
        return placed(deviceUid, directory.roomOf(deviceUid), rooms);
    }

    private Placed placed(String deviceUid, Optional<String> roomUid, Map<String, Room> plan) {
        if (roomUid.isEmpty()) {
            return new Placed("", unplaced.nameOf(deviceUid), "", limits.defaultLimit());
        }
        Room room = plan.get(roomUid.get());
        if (room == null) {
            return new Placed(roomUid.get(), "room " + roomUid.get(), "", limits.limitForUnknownRoom(roomUid.get()));
        }
        return new Placed(room.uid(), room.name(), room.type(), limits.limitFor(room));
    }

    /** @return the type of a room House Information knows, else empty */
    String typeOf(String roomUid) {
        Room r = rooms.get(roomUid);
        return r == null ? "" : r.type();
    }

    int knownRooms() {
        return rooms.size();
    }
}
