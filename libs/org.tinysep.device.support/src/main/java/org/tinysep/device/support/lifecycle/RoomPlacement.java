package org.tinysep.device.support.lifecycle;

import java.util.List;
import java.util.function.BiConsumer;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.rooms.Rooms;

/**
 * The {@code room} parameter of a device: validated against House Information, published as service property
 * {@link DeviceProperties#ROOM} on all the device's services, cleared when the room is removed from the house.
 */
final class RoomPlacement {

    static final String KEY = "room";

    private final String deviceUid;
    private final DriverContext context;
    private final BiConsumer<String, Object> property;
    private final Runnable changed;
    private volatile String roomUid;
    private Connection watch;

    RoomPlacement(String deviceUid, DriverContext context, BiConsumer<String, Object> property) {
        this(deviceUid, context, property, () -> { });
    }

    /** @param changed told when the room changed by itself (the room was removed from the house) */
    RoomPlacement(String deviceUid, DriverContext context, BiConsumer<String, Object> property, Runnable changed) {
        this.deviceUid = deviceUid;
        this.context = context;
        this.property = property;
        this.changed = changed;
    }

    Parameter parameter() {
        String uid = roomUid;
        String shown = uid == null ? "" : context.rooms().room(uid).map(Rooms::label).orElse(uid);
        return Parameter.writable(KEY, shown, "room of the device: UID, unique UID prefix or name; empty to clear");
    }

    /** @return the UID of the room the device is in, or null */
    String roomUid() {
        return roomUid;
    }

    void set(String value) {
        if (value == null || value.isBlank()) {
            place(null);
            context.reporter().event(EventKind.DEVICE_EVENT, deviceUid, "room cleared");
            return;
        }
        Room room = context.rooms().resolve(value);
        watchHouse();
        place(room.uid());
        context.reporter().event(EventKind.DEVICE_EVENT, deviceUid, "placed in room " + Rooms.label(room));
    }

    /**
     * Places the device in a room saved in its backup, before it registers: House Information may not be running
     * yet, so the UID is taken as it is; when the house is there and lacks the room, the device is unplaced.
     */
    void restore(String uid) {
        if (uid == null || uid.isBlank()) {
            return;
        }
        watchHouse();
        place(uid.strip());
        context.rooms().house().ifPresent(h -> houseChanged(h.rooms()));
    }

    private synchronized void watchHouse() {
        if (watch == null) { // from the first placement on, a removed room is cleared
            watch = context.rooms().watch(this::houseChanged);
        }
    }

    private void place(String uid) {
        roomUid = uid;
        property.accept(DeviceProperties.ROOM, uid);
    }

    /** Stops watching the house; called when the device goes. */
    synchronized void close() {
        if (watch != null) {
            watch.close();
            watch = null;
        }
    }

    void houseChanged(List<Room> rooms) {
        String uid = roomUid;
        if (uid != null && rooms.stream().noneMatch(r -> r.uid().equals(uid))) {
            place(null);
            context.reporter().event(EventKind.DEVICE_EVENT, deviceUid, "room " + uid
                    + " was removed from the house; the device is no longer placed");
            changed.run();
        }
    }
}
