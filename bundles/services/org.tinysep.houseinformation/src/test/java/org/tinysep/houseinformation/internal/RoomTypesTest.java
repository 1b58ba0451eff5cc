package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** room-add refuses a room type it does not know (a typo would silently get the default inactivity limit). */
class RoomTypesTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    @TempDir
    Path dir;

    private HouseDevice house() {
        return new HouseDevice(new DriverContext(null, "drv", "HouseInformation", new RecordingLogs(() -> T0).reporter(),
                new PlatformClock(() -> T0)), new HouseFile(dir.resolve("house.xml"), new HouseCodec()));
    }

    @Test
    void anUnknownTypeIsRefusedUnlessItIsDeclaredNew() {
        HouseDevice house = house();
        HouseCommands c = new HouseCommands(house, Map::of);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.add("Bath", "Bathrom"));
        assertTrue(e.getMessage().startsWith("unknown room type 'Bathrom'; known types: Bathroom, Bedroom, Hall,"
                + " Kitchen, Living room, Study, Toilet."), e.getMessage());
        assertTrue(e.getMessage().endsWith("add --new-type"), e.getMessage());
        assertEquals(List.of(), house.rooms(), "nothing added");

        assertTrue(c.add("Bath", "bathroom").endsWith(", type Bathroom"), "known types match ignoring case");
        String garage = c.add("Garage", "Garage", true);
        assertTrue(garage.endsWith("type Garage (a new type: Inactivity Recognition uses its default limit for it"
                + " until its typeLimits names it)"), garage);
        assertTrue(c.add("Car port", "garage").endsWith(", type Garage"), "a type a room has is known");
        assertThrows(IllegalArgumentException.class, () -> c.rename("Bath", "Bath", "Sauna"));
    }

    @Test
    void commandsGiveTheirUsageAndHelpInsteadOfGogosCoercionError() {
        ShellFunctions.Command add = new ShellFunctions.Command("room-add <name> <type> [--new-type]", "adds a room",
                List.of("<name>: the room's name"), 2, 2, (a, isNew) -> a + " " + isNew);
        assertEquals("missing arguments; usage: room-add <name> <type> [--new-type] (tinysep:room-add --help"
                + " explains)", assertThrows(IllegalArgumentException.class,
                        () -> add.execute(null, List.of("Garage"))).getMessage());
        assertEquals("tinysep:room-add <name> <type> [--new-type]\n  adds a room\n  <name>: the room's name",
                add.execute(null, List.of("--help")));
        assertEquals("[Garage, Garage] true", add.execute(null, List.of("Garage", "--new-type", "Garage")));
    }
}
