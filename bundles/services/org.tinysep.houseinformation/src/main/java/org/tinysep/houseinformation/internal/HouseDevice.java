package org.tinysep.houseinformation.internal;

import java.io.IOException;
import java.util.List;
import java.util.Optional;
import java.util.UUID;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.HouseInformationListener;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;
import org.tinysep.device.support.rooms.Rooms;

/**
 * The House Information device: holds the plan, validates every change, saves it, then tells listeners and the
 * event log. A malformed file on start makes the status ERROR with the reason (the last good house is used).
 */
final class HouseDevice extends WholeFlatDevice implements HouseInformationProvider {

    private static final Logger LOG = LoggerFactory.getLogger(HouseDevice.class);

    private final HouseFile file;
    private final Listeners<HouseInformationListener> listeners;
    private volatile HousePlan plan = HousePlan.EMPTY;

    HouseDevice(DriverContext context, HouseFile file) {
        super(context, Uids.of(context.driverName(), "house"), context.driverName(), "House");
        this.file = file;
        this.listeners = new Listeners<>(uid());
        publish(this, HouseInformationProvider.class);
        load();
    }

    private void load() {
        try {
            HouseFile.Load l = file.load(now());
            plan = l.plan();
            if (l.problem() == null) {
                status(DeviceStatus.State.ONLINE, plan.rooms().size() + " rooms from " + file.path());
            } else {
                LOG.warn("Malformed house file: {}", l.problem());
                problem(l.problem());
            }
        } catch (IOException | RuntimeException e) {
            LOG.warn("Cannot read house file {}: {}", file.path(), e.toString());
            problem("cannot read " + file.path() + ": " + e.getMessage());
        }
    }

    private void problem(String reason) {
        status(DeviceStatus.State.ERROR, reason);
        context.reporter().event(EventKind.PROBLEM, uid(), reason);
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(HouseInformationListener listener) {
        return listeners.add(listener);
    }

    @Override
    public List<Room> rooms() {
        return plan.rooms();
    }

    @Override
    public Optional<Room> room(String uid) {
        return plan.room(uid);
    }

    @Override
    public Room addRoom(String name, String type) {
        String uid = UUID.randomUUID().toString();
        HousePlan next = change(p -> p.withRoom(uid, name, type), p -> "room added: " + label(p, uid));
        return next.existing(uid);
    }

    @Override
    public Room updateRoom(String uid, String name, String type) {
        plan.existing(uid);
        return change(p -> p.withRoom(uid, name, type), p -> "room updated: " + label(p, uid) + ", type "
                + p.existing(uid).type()).existing(uid);
    }

    @Override
    public void link(String roomUid, String otherRoomUid) {
        change(p -> p.linked(roomUid, otherRoomUid, true), p -> "rooms linked: " + label(p, roomUid) + " <-> "
                + label(p, otherRoomUid));
    }

    @Override
    public void unlink(String roomUid, String otherRoomUid) {
        change(p -> p.linked(roomUid, otherRoomUid, false), p -> "rooms unlinked: " + label(p, roomUid) + " <-> "
                + label(p, otherRoomUid));
    }

    @Override
    public boolean removeRoom(String uid) {
        if (plan.room(uid).isEmpty()) {
            return false;
        }
        String removed = label(plan, uid);
        change(p -> p.without(uid), p -> "room removed: " + removed);
        return true;
    }

    /** Validates, saves, then announces one change; the plan is unchanged if any step fails. */
    private synchronized HousePlan change(UnaryOperator<HousePlan> edit, Function<HousePlan, String> what) {
        HousePlan next = edit.apply(plan);
        try {
            file.save(next);
        } catch (IOException | RuntimeException e) {
            String reason = "cannot save the house to " + file.path() + ": " + e;
            problem(reason);
            throw new IllegalStateException(reason, e);
        }
        plan = next;
        status(DeviceStatus.State.ONLINE, next.rooms().size() + " rooms in " + file.path());
        event(what.apply(next));
        List<Room> rooms = next.rooms();
        listeners.fire(l -> l.houseChanged(this, rooms, now()));
        return next;
    }

    private static String label(HousePlan p, String uid) {
        return p.room(uid).map(Rooms::label).orElse(uid);
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(Parameter.readOnly("file", file.path(), "the house XML file (config key 'file')"),
                Parameter.readOnly("rooms", plan.rooms().size(), "number of rooms"));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
