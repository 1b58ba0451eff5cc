package org.tinysep.device.support.rooms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.Room;

class RoomsTest {

    private final Room bath = new Room("0cf52171-0d00-486f-bbb2-e6ef950012b5", "Bathroom", "Bathroom", Set.of());
    private final Room kitchen = new Room("0cf5aaaa-0000-4000-8000-000000000001", "Kitchen", "Kitchen", Set.of());
    private final Room kitchen2 = new Room("9ffbd81c-9ab3-4bf7-8b13-8ab31634ebf5", "kitchen", "Kitchen", Set.of());
    private final List<Room> rooms = List.of(bath, kitchen);

    @Test
    void findsByUidPrefixOrNameIgnoringCase() {
        assertEquals(bath, Rooms.resolve(rooms, bath.uid()));
        assertEquals(bath, Rooms.resolve(rooms, bath.uid().toUpperCase()));
        assertEquals(bath, Rooms.resolve(rooms, "0cf52"));
        assertEquals(bath, Rooms.resolve(rooms, " bathROOM "));
        assertEquals(kitchen, Rooms.resolve(rooms, "KITCHEN"));
    }

    @Test
    void rejectsUnknownShortAndAmbiguousQueries() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Rooms.resolve(rooms, "Garage"));
        assertEquals("unknown room 'Garage'; known rooms: Bathroom (" + bath.uid() + "), Kitchen ("
                + kitchen.uid() + ")", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Rooms.resolve(rooms, "0cf5"));
        assertTrue(e.getMessage().startsWith("UID prefix '0cf5' is ambiguous: "), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Rooms.resolve(rooms, "0cf"));
        assertTrue(e.getMessage().startsWith("unknown room '0cf'"), "3 characters are too short a prefix");
        e = assertThrows(IllegalArgumentException.class, () -> Rooms.resolve(List.of(kitchen, kitchen2), "Kitchen"));
        assertTrue(e.getMessage().startsWith("room name 'Kitchen' is ambiguous"), e.getMessage());
        assertEquals("no room given", assertThrows(IllegalArgumentException.class,
                () -> Rooms.resolve(rooms, " ")).getMessage());
    }
}
