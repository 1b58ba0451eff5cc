package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.service.FlatOccupancyListener;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;

/**
 * The one Flat Occupancy device (thesis 4.4.3.1). Connects to every Movement and Door provider; each connection
 * counts as vital. Unlike thesis Fig 3.4 it is not removed when it has none left: it watches the person,
 * keeps running and says which rooms it can no longer see; it goes only with its driver.
 */
final class FlatOccupancyDevice extends WholeFlatDevice
        implements FlatOccupancyProvider, MovementListener, DoorListener, WindowListener, PresenceListener {

    /**
     * Sensor Health's unmonitored rooms in words, e.g. "Bathroom (no sensor heard since 2026-11-25T09:12:00Z)";
     * empty without Sensor Health.
     */
    private volatile Supplier<String> unmonitored = () -> "";
    private volatile Consumer<Instant> due = at -> { };
    private final Listeners<FlatOccupancyListener> listeners;
    private final OccupancyLogic logic;
    private final Duration leaveTimeout;
    /** Why a leave check ended in UNOCCUPIED, in the event's words (the same for every leave check). */
    private final String leaveReason;
    private final Set<String> windows = ConcurrentHashMap.newKeySet();

    FlatOccupancyDevice(DriverContext context, Duration leaveTimeout, Duration exitGrace) {
        super(context, Uids.of(context.driverName(), "flat"), context.driverName(), "Flat occupancy");
        this.listeners = new Listeners<>(uid());
        this.leaveTimeout = leaveTimeout;
        this.leaveReason = "no indoor activity for " + leaveTimeout.toSeconds() + " s after the door closed";
        this.logic = new OccupancyLogic(leaveTimeout, exitGrace, context.now());
        publish(this, FlatOccupancyProvider.class);
    }

    void watch(MovementProvider movement) {
        connect(movement, MovementProvider.class, this, true);
    }

    void watch(DoorProvider door) {
        connect(door, DoorProvider.class, this, true);
    }

    /** Windows and contacts on furniture are evidence, not a reason for this device to exist (thesis Fig 3.3). */
    void watch(WindowProvider window) {
        if (!windows.add(window.deviceUid())) {
            return; // the driver's tracker and a new device may both offer it
        }
        connect(window, WindowProvider.class, this, false);
    }

    /** Mats, flush and appliances: evidence, and a home with nothing else still has a Flat Occupancy. */
    void watch(PresenceProvider presence) {
        connect(presence, PresenceProvider.class, this, true);
        if (presence.kind().holdsPerson() && presence.present()) {
            synchronized (logic) {
                logic.holdsPerson(presence.deviceUid(), true, true, now());
            }
        }
    }

    /** A provider went away (the driver closes the connection): a mat no longer says anyone is here. */
    void forget(String providerUid) {
        windows.remove(providerUid);
        synchronized (logic) {
            logic.forget(providerUid);
        }
    }

    /** A window's or contact's change is activity; its first report (after its device started) only its state. */
    @Override
    public void windowChanged(WindowProvider source, OpenState state, boolean first, Instant at) {
        if (!first && state != OpenState.UNKNOWN) {
            activity(at, () -> "window " + source.deviceUid() + " " + state.name().toLowerCase());
        }
    }

    /** A caller of the sensor API 1.0 call reports a change. */
    @Override
    public void windowChanged(WindowProvider source, OpenState state, Instant at) {
        windowChanged(source, state, false, at);
    }

    @Override
    public void presenceChanged(PresenceProvider source, boolean present, boolean first, Instant at) {
        if (first && !present) {
            return;
        }
        Optional<Occupancy> change = step(now(), l -> source.kind().holdsPerson()
                ? l.holdsPerson(source.deviceUid(), present, first, at)
                : first ? Optional.empty() : l.indoorActivity(at));
        announce(change, at, () -> source.kind().name().toLowerCase() + " " + source.deviceUid() + " "
                + (present ? "on" : "off"));
    }

    /** Indoor activity other than motion (an inner door, a window, a contact). */
    private void activity(Instant at, Supplier<String> what) {
        announce(step(now(), l -> l.indoorActivity(at)), at, what);
    }

    /**
     * The radio's delivery thread calls this for every report of every movement sensor: one step of the logic and
     * nothing else (no closure, no time arithmetic); the event's words are built only when the decision changes.
     */
    @Override
    public void movementReported(MovementProvider source, MovementEvent movement) {
        if (!movement.detected() || source.location() != MovementLocation.INSIDE) {
            return;
        }
        Instant now = now();
        Instant at = movement.at();
        Optional<Occupancy> change;
        Optional<Instant> wentBack;
        synchronized (logic) {
            wentBack = logic.rebase(now);
            change = logic.motion(at);
        }
        if (wentBack.isPresent()) {
            clockWentBack(wentBack.get(), now);
        }
        if (change.isPresent()) {
            announce(change.get(), at, "motion from " + source.deviceUid());
        }
    }

    /**
     * A door's first report (after its device started) tells its state: a first CLOSED is no evidence that anyone
     * left; a first OPEN of the outer door counts as an opening. An inner door's change is indoor activity.
     */
    @Override
    public void doorChanged(DoorProvider source, OpenState state, boolean first, Instant at) {
        if (state == OpenState.UNKNOWN || (first && state == OpenState.CLOSED)) {
            return;
        }
        if (source.kind() != DoorKind.OUTER) {
            if (!first) {
                activity(at, () -> "inner door " + source.deviceUid() + " " + state.name().toLowerCase());
            }
            return;
        }
        Optional<Occupancy> change = step(now(),
                l -> state == OpenState.OPEN ? l.outerDoorOpened(at) : l.outerDoorClosed(at));
        if (state == OpenState.CLOSED) {
            saveBackup(); // a pending leave check survives a crash
        }
        announce(change, at, () -> "outer door " + source.deviceUid() + " " + state.name().toLowerCase());
    }

    /** A caller of the sensor API 1.0 call reports a change. */
    @Override
    public void doorChanged(DoorProvider source, OpenState state, Instant at) {
        doorChanged(source, state, false, at);
    }

    /**
     * Advances the algorithm's clock; called by the driver's ticker when due.
     *
     * @return when it is next due: the end of the pending leave check, null without one
     */
    Instant tick(Instant now) {
        announce(step(now, l -> l.tick(now)), now, () -> leaveReason);
        return leaveCheckEnd();
    }

    /** Where the device says that a leave check began: its end needs a tick (the driver's ticker). */
    void whenDue(Consumer<Instant> due) {
        this.due = due;
    }

    private Instant leaveCheckEnd() {
        synchronized (logic) {
            return logic.leaveDeadline().orElse(null);
        }
    }

    /**
     * One step of the algorithm at the platform's time {@code now} (not the report's: a late report is no clock
     * step): re-bases the logic's times first if the clock went back, and says so.
     *
     * @return the decision's change, if any
     */
    private Optional<Occupancy> step(Instant now, Function<OccupancyLogic, Optional<Occupancy>> step) {
        Optional<Occupancy> change;
        Optional<Instant> wentBack;
        synchronized (logic) {
            wentBack = logic.rebase(now);
            change = step.apply(logic);
            due.accept(logic.leaveDeadline().orElse(null)); // a door closed: its leave check ends later
        }
        if (wentBack.isPresent()) {
            clockWentBack(wentBack.get(), now);
        }
        return change;
    }

    /** Announces a change, if any; {@code reason} is asked for its words only then. */
    private void announce(Optional<Occupancy> change, Instant at, Supplier<String> reason) {
        if (change.isPresent()) {
            announce(change.get(), at, reason.get());
        }
    }

    private void announce(Occupancy o, Instant at, String reason) {
        status(DeviceStatus.State.ONLINE, "");
        event("flat " + o.name().toLowerCase() + " (" + reason + ")");
        saveBackup(); // the decision survives a restart
        listeners.fire(l -> l.occupancyChanged(this, o, at));
    }

    /** The clock went back from {@code from}: says so (the logic already re-based its times on the new clock). */
    private void clockWentBack(Instant from, Instant now) {
        event("clock went back from " + from.truncatedTo(ChronoUnit.SECONDS) + " to "
                + now.truncatedTo(ChronoUnit.SECONDS) + ": occupancy times and any leave check counted "
                + "from now");
        saveBackup();
    }

    @Override
    protected Map<String, String> backupState() {
        synchronized (logic) {
            return SavedOccupancy.toState(logic.saved());
        }
    }

    /**
     * After a restart: resumes from the saved decision (with its since and any pending leave check) instead of
     * UNKNOWN, so Inactivity Recognition keeps watching someone already home; times from the future are counted
     * from now.
     */
    @Override
    protected void onRestore(ComponentBackup saved) {
        List<String> problems = new ArrayList<>();
        OccupancyLogic.Saved s = SavedOccupancy.fromState(saved.state(), problems);
        problems.forEach(p -> context.reporter().event(EventKind.PROBLEM, uid(), p));
        if (s == null) {
            return;
        }
        Instant now = now();
        Optional<Instant> wentBack;
        synchronized (logic) {
            logic.restore(s);
            wentBack = logic.rebase(now);
            due.accept(logic.leaveDeadline().orElse(null));
        }
        status(DeviceStatus.State.ONLINE, "");
        event("restored after a restart: flat " + s.state().name().toLowerCase() + " since " + s.since()
                + (s.leaveDeadline() == null ? "" : ", leave check until " + s.leaveDeadline()));
        wentBack.ifPresent(f -> event("saved state from the future (" + f + ", now " + now
                + "): counted from now"));
    }

    /** It stays when its sensors go and says which rooms it can no longer see. */
    @Override
    protected boolean watchesThePerson() {
        return true;
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(FlatOccupancyListener listener) {
        return listeners.add(listener);
    }

    @Override
    public Occupancy occupancy() {
        synchronized (logic) {
            return logic.state();
        }
    }

    @Override
    public Instant since() {
        synchronized (logic) {
            return logic.since();
        }
    }

    /** Where the device reads the rooms that cannot be watched now (the driver's Sensor Health, optional). */
    void unmonitored(Supplier<String> rooms) {
        unmonitored = rooms;
    }

    @Override
    protected List<Parameter> moreParameters() {
        synchronized (logic) {
            return List.of(
                    Parameter.readOnly("occupancy", logic.state(), "current decision"),
                    Parameter.readOnly("since", logic.since(), "when it was reached"),
                    Parameter.readOnly("leaveCheckUntil", logic.leaveDeadline().map(Instant::toString).orElse(""),
                            "end of the pending leave check"),
                    Parameter.readOnly("someoneHere", String.join(", ", logic.here()),
                            "bed or seat mats that are ON (the flat stays occupied while any is)"),
                    Parameter.readOnly("unmonitoredRooms", unmonitored.get(), "rooms none of whose sensors can be "
                            + "heard now (Sensor Health): activity there cannot cancel a leave check"),
                    Parameter.readOnly("leaveTimeoutSeconds", leaveTimeout.toSeconds(),
                            "configured in pid org.tinysep.flatoccupancy"));
        }
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
