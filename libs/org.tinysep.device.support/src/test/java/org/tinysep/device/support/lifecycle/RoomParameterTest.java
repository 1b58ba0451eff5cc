package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/** The {@code room} parameter every placeable device has. */
class RoomParameterTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private static final class Sensor extends AbstractDevice {
        private final boolean placeable;

        Sensor(DriverContext c, boolean placeable) {
            super(c, "dev-1", "Sensor", "Sensor 1");
            this.placeable = placeable;
        }

        @Override
        protected boolean placeable() {
            return placeable;
        }

        String roomProperty() {
            return roomUid();
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final FakeHouse house = new FakeHouse();
    private final Room bath = house.add("0cf52171-0d00-486f-bbb2-e6ef950012b5", "Bathroom");

    private DriverContext context(RoomDirectory rooms) {
        return new DriverContext(null, "drv", "Sensor", logs.reporter(), new PlatformClock(() -> T0), rooms);
    }

    private static Parameter room(AbstractDevice d) {
        return d.parameters().stream().filter(p -> p.key().equals("room")).findFirst().orElseThrow();
    }

    @Test
    void placedByNameShownAsNameAndUidAndClearedByEmpty() {
        Sensor s = new Sensor(context(RoomDirectory.of(house)), true);
        assertEquals("", room(s).value());
        assertTrue(room(s).writable());
        s.setParameter("room", "bathroom");
        assertEquals(bath.uid(), s.roomProperty());
        assertEquals("Bathroom (" + bath.uid() + ")", room(s).value());
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("placed in room Bathroom (" + bath.uid()
                + ")")));
        house.updateRoom(bath.uid(), "Bath", "Bathroom");
        assertEquals("Bath (" + bath.uid() + ")", room(s).value(), "a rename shows at once");
        s.setParameter("room", "");
        assertNull(s.roomProperty());
        assertEquals("", room(s).value());
    }

    @Test
    void unknownRoomIsRejectedAndTheDeviceUnchanged() {
        Sensor s = new Sensor(context(RoomDirectory.of(house)), true);
        s.setParameter("room", "0cf52171");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> s.setParameter("room", "Garage"));
        assertTrue(e.getMessage().startsWith("unknown room 'Garage'; known rooms: Bathroom"), e.getMessage());
        assertEquals(bath.uid(), s.roomProperty());
    }

    @Test
    void withoutHouseInformationSettingFailsClearly() {
        Sensor s = new Sensor(context(RoomDirectory.none()), true);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> s.setParameter("room", "Bathroom"));
        assertEquals(RoomDirectory.NO_HOUSE, e.getMessage());
        // the framework-free constructor of existing tests keeps working and knows no house
        DriverContext plain = new DriverContext(null, "d", "X", logs.reporter(), new PlatformClock(() -> T0));
        assertThrows(IllegalArgumentException.class, () -> new Sensor(plain, true).setParameter("room", "x"));
    }

    @Test
    void removingTheRoomClearsTheDeviceAndLogsIt() {
        Sensor s = new Sensor(context(RoomDirectory.of(house)), true);
        s.setParameter("room", "Bathroom");
        house.add("other", "Kitchen");
        assertEquals(bath.uid(), s.roomProperty(), "other changes keep the room");
        house.removeRoom(bath.uid());
        assertNull(s.roomProperty());
        assertTrue(logs.events().stream().anyMatch(e -> e.message().contains("was removed from the house")));
    }

    @Test
    void notPlaceableDevicesHaveNoRoomParameter() {
        Sensor s = new Sensor(context(RoomDirectory.of(house)), false);
        assertFalse(s.parameters().stream().anyMatch(p -> p.key().equals("room")));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> s.setParameter("room", "Bathroom"));
        assertEquals("unknown or read-only parameter 'room' of Sensor; writable: name", e.getMessage());
    }

    /** A service of the whole flat declares so once, by its base class: no room parameter, none in its backup. */
    @Test
    void wholeFlatDevicesHaveNoRoomParameterAndKeepNoRoom() {
        WholeFlatDevice flat = new WholeFlatDevice(context(RoomDirectory.of(house)), "flat-1", "Flat", "Flat 1") {
        };
        assertEquals(java.util.List.of("name"), flat.parameters().stream().map(Parameter::key).toList());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> flat.setParameter("room", bath.uid()));
        assertEquals("unknown or read-only parameter 'room' of Flat; writable: name", e.getMessage());
        assertFalse(flat.backup().parameters().containsKey("room"));
    }
}
