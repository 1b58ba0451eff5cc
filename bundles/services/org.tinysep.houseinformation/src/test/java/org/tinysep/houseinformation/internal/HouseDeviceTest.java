package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** Changes are validated, saved, then announced; a malformed file makes the device report ERROR. */
class HouseDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    @TempDir
    Path dir;

    private final RecordingLogs logs = new RecordingLogs(() -> T0);

    private HouseDevice device() {
        return new HouseDevice(new DriverContext(null, "drv", "HouseInformation", logs.reporter(),
                new PlatformClock(() -> T0)), new HouseFile(dir.resolve("house.xml"), new HouseCodec()));
    }

    @Test
    void changesAreSavedThenAnnouncedWithTheWholePlan() throws Exception {
        HouseDevice house = device();
        assertEquals(DeviceStatus.State.ONLINE, house.status().state());
        List<List<Room>> heard = new ArrayList<>();
        house.connect((source, rooms, at) -> {
            assertTrue(Files.exists(dir.resolve("house.xml")), "saved before announced");
            heard.add(rooms);
        });
        Room bed = house.addRoom("Master Bedroom", "Bedroom");
        Room bath = house.addRoom(" Bathroom ", "Bathroom");
        assertEquals("Bathroom", bath.name());
        house.link(bed.uid(), bath.uid());
        assertEquals(Set.of(bath.uid()), house.room(bed.uid()).orElseThrow().neighbours());
        assertEquals(Set.of(bed.uid()), house.room(bath.uid()).orElseThrow().neighbours(), "links are symmetric");
        house.updateRoom(bath.uid(), "Bath", "Bathroom");
        house.unlink(bath.uid(), bed.uid());
        assertEquals(Set.of(), house.room(bed.uid()).orElseThrow().neighbours());
        house.link(bed.uid(), bath.uid());
        assertTrue(house.removeRoom(bath.uid()));
        assertFalse(house.removeRoom(bath.uid()));
        assertEquals(List.of(new Room(bed.uid(), "Master Bedroom", "Bedroom", Set.of())), house.rooms(),
                "removing a room removes its links");
        assertEquals(7, heard.size());
        assertEquals(house.rooms(), heard.get(6));
        assertEquals(house.rooms(), device().rooms(), "reloaded from the file");
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("room added: Master Bedroom ("
                + bed.uid() + ")")));
    }

    @Test
    void badChangesAreRejectedClearlyAndChangeNothing() throws Exception {
        HouseDevice house = device();
        Room a = house.addRoom("A", "Hall");
        byte[] saved = Files.readAllBytes(dir.resolve("house.xml"));
        assertEquals("room name must not be blank", assertThrows(IllegalArgumentException.class,
                () -> house.addRoom(" ", "Hall")).getMessage());
        assertEquals("room type must not be blank", assertThrows(IllegalArgumentException.class,
                () -> house.addRoom("B", "")).getMessage());
        assertEquals("unknown room UID 'nope'", assertThrows(IllegalArgumentException.class,
                () -> house.link(a.uid(), "nope")).getMessage());
        assertEquals("a room cannot be linked to itself: A", assertThrows(IllegalArgumentException.class,
                () -> house.link(a.uid(), a.uid())).getMessage());
        assertEquals("unknown room UID 'nope'", assertThrows(IllegalArgumentException.class,
                () -> house.updateRoom("nope", "X", "Y")).getMessage());
        assertEquals(List.of(a), house.rooms());
        assertEquals(new String(saved), Files.readString(dir.resolve("house.xml")));
    }

    @Test
    void aMalformedFileIsReportedAsStatusAndProblemEvent() throws Exception {
        HouseDevice first = device();
        Room a = first.addRoom("A", "Hall");
        first.addRoom("B", "Hall"); // .bak holds A only
        Files.writeString(dir.resolve("house.xml"), "<HOUSE_ROOMS><ROOM>");
        HouseDevice house = device();
        assertEquals(List.of(a), house.rooms());
        assertEquals(DeviceStatus.State.ERROR, house.status().state());
        assertTrue(house.status().detail().contains("bad XML"), house.status().detail());
        assertTrue(house.status().detail().contains("using the last good house from house.xml.bak (1 rooms)"),
                house.status().detail());
        assertEquals(1, logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).count());
        house.addRoom("C", "Hall");
        assertEquals(DeviceStatus.State.ONLINE, house.status().state(), "a good save clears the error");
    }
}
