package org.tinysep.device.support;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.HouseInformationListener;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;

/** An in-memory fake of the HouseInformationProvider contract (no links, no persistence). */
final class FakeHouse implements HouseInformationProvider {

    private final Map<String, Room> rooms = new LinkedHashMap<>();
    private final Listeners<HouseInformationListener> listeners = new Listeners<>("house");

    Room add(String uid, String name) {
        Room r = new Room(uid, name, "Room", Set.of());
        rooms.put(uid, r);
        changed();
        return r;
    }

    private void changed() {
        List<Room> all = rooms();
        listeners.fire(l -> l.houseChanged(this, all, Instant.EPOCH));
    }

    @Override
    public String deviceUid() {
        return "house";
    }

    @Override
    public Connection connect(HouseInformationListener listener) {
        return listeners.add(listener);
    }

    @Override
    public List<Room> rooms() {
        return List.copyOf(new ArrayList<>(rooms.values()));
    }

    @Override
    public Optional<Room> room(String uid) {
        return Optional.ofNullable(rooms.get(uid));
    }

    @Override
    public Room addRoom(String name, String type) {
        throw new UnsupportedOperationException();
    }

    @Override
    public Room updateRoom(String uid, String name, String type) {
        Room r = new Room(uid, name, type, Set.of());
        rooms.put(uid, r);
        changed();
        return r;
    }

    @Override
    public void link(String roomUid, String otherRoomUid) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void unlink(String roomUid, String otherRoomUid) {
        throw new UnsupportedOperationException();
    }

    @Override
    public boolean removeRoom(String uid) {
        boolean had = rooms.remove(uid) != null;
        changed();
        return had;
    }
}
