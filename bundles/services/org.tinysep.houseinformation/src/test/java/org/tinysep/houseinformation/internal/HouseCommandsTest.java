package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

class HouseCommandsTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    @TempDir
    Path dir;

    @Test
    void commandsResolveRoomsByNameOrPrefixAndListThem() {
        RecordingLogs logs = new RecordingLogs(() -> T0);
        HouseDevice house = new HouseDevice(new DriverContext(null, "drv", "HouseInformation", logs.reporter(),
                new PlatformClock(() -> T0)), new HouseFile(dir.resolve("house.xml"), new HouseCodec()));
        HouseCommands c = new HouseCommands(house, () -> Map.of());
        assertEquals("no rooms; add one with: room-add <name> <type>", c.rooms());
        assertTrue(c.add("Kitchen", "Kitchen").startsWith("added Kitchen ("));
        c.add("Hall", "Hall");
        Room kitchen = house.rooms().get(0);
        assertEquals("linked Kitchen <-> Hall", c.link("kitchen", "HALL"));
        assertEquals(Set.of(kitchen.uid()), house.rooms().get(1).neighbours());
        assertTrue(c.rename(kitchen.uid().substring(0, 6), "Cuisine", null).endsWith(", type Kitchen"));
        String table = new HouseCommands(house, () -> Map.of(kitchen.uid(), List.of("Motion 1.17"))).rooms();
        assertTrue(table.startsWith("UID"), table);
        assertTrue(table.lines().anyMatch(l -> l.startsWith(kitchen.uid()) && l.contains("Cuisine")
                && l.contains("Hall") && l.endsWith("Motion 1.17")), table);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.remove("Garage"));
        assertTrue(e.getMessage().startsWith("unknown room 'Garage'; known rooms: Cuisine ("), e.getMessage());
        assertEquals("removed Hall (" + house.rooms().get(1).uid() + ")", c.remove("hall"));
        assertEquals(Set.of(), house.rooms().get(0).neighbours());
    }

    @Test
    void defaultFileFollowsTinysepHome() {
        assertEquals(Path.of("/opt/t/var/house.xml"), HouseInformation.houseFile("", null, "/opt/t"));
        assertEquals(Path.of("/srv/state/house.xml"), HouseInformation.houseFile("", "/srv/state", "/opt/t"));
        assertEquals(Path.of("/etc/h.xml"), HouseInformation.houseFile(" /etc/h.xml ", "/srv/state", "/opt/t"));
        assertEquals(Path.of("house.xml").toAbsolutePath(), HouseInformation.houseFile(null, null, null));
    }
}
