package org.tinysep.device.support.testing;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.tinysep.api.service.HouseInformationListener;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;

/**
 * An in-memory House Information for unit tests (no links, no persistence): {@link #add}, {@link #updateRoom} and
 * {@link #removeRoom} change the rooms and tell the listeners; adding a room by name and linking are unsupported.
 */
public final class FakeHouse extends FakeProvider<HouseInformationListener> implements HouseInformationProvider {

    private final Map<String, Room> rooms = new LinkedHashMap<>();

    /** @param initial the rooms the house starts with (no listener is told about them) */
    public FakeHouse(Room... initial) {
        super("house");
        for (Room r : initial) {
            rooms.put(r.uid(), r);
        }
    }

    /** Adds a room of type {@code Room} and tells the listeners. */
    public Room add(String uid, String name) {
        Room r = new Room(uid, name, "Room", Set.of());
        rooms.put(uid, r);
        changed();
        return r;
    }

    private void changed() {
        List<Room> all = rooms();
        List.copyOf(listeners).forEach(l -> l.houseChanged(this, all, Instant.EPOCH));
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
