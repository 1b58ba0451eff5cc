package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.testing.MutableClock;
import org.tinysep.runtime.internal.directory.Home;
import org.tinysep.runtime.internal.log.EventLogService;
import org.tinysep.runtime.internal.log.LogSeams;
import org.tinysep.runtime.internal.log.PacketLogService;

/** The log commands' output is a contract (integration tests parse it), and so are their options. */
class HistoryCommandsTest {

    static final Instant START = Instant.parse("2026-11-22T11:10:00.123456Z");

    @TempDir
    Path dir;

    private final Home home = new Home();
    private final MutableClock time = new MutableClock(START);
    private final EventLogService events = LogSeams.events(time, 100);
    private final PacketLogService packets = LogSeams.packets(time, 100);
    private final HistoryCommands shell = new HistoryCommands(home.directory, events, packets, time);

    @AfterEach
    void close() {
        LogSeams.keepIn(events, null);
        LogSeams.keepIn(packets, null);
    }

    private void persist() {
        LogSeams.keepIn(events, dir);
        LogSeams.keepIn(packets, dir);
    }

    @Test
    void logShowsTheNewestEntriesOldestFirst() {
        for (int i = 1; i <= 25; i++) {
            events.record(EventKind.DEVICE_EVENT, "door-" + i, "door opened");
        }
        events.record(EventKind.PROBLEM, "", "bad | input\nsecond line");
        List<String> lines = shell.log().lines().toList();
        assertEquals(21, lines.size(), "header and the default 20");
        assertEquals("SEQ | TIME                     | KIND         | ORIGIN  | MESSAGE", lines.get(0));
        assertEquals("7   | 2026-11-22T11:10:00.123Z | DEVICE_EVENT | door-7  | door opened", lines.get(1));
        assertEquals("26  | 2026-11-22T11:10:00.123Z | PROBLEM      | -       | bad | input second line",
                lines.get(20));
        assertEquals(3, shell.log("2").lines().count());
        assertEquals(shell.log("5"), shell.events("5"));
        assertEquals(shell.log("5"), shell.events("--limit", "5"));
    }

    @Test
    void packetsShowDecimalAndHexBytes() {
        packets.record(Direction.RECEIVED, "busradio-amica 127.0.0.1:47001", new byte[] {(byte) 170, 1, 18, (byte) 255},
                "");
        packets.record(Direction.SENT, "busradio-amica", new byte[] {2, 16}, "");
        packets.record(Direction.RECEIVED, "busradio-amica", new byte[0], "checksum mismatch");
        assertEquals(String.join("\n",
                "SEQ | TIME                     | DIRECTION | ORIGIN                         | DECIMAL      | HEX         | NOTE",
                "1   | 2026-11-22T11:10:00.123Z | RECEIVED  | busradio-amica 127.0.0.1:47001 | 170 1 18 255 | AA 01 12 FF | -",
                "2   | 2026-11-22T11:10:00.123Z | SENT      | busradio-amica                 | 2 16         | 02 10       | -",
                "3   | 2026-11-22T11:10:00.123Z | RECEIVED  | busradio-amica                 | -            | -           | checksum mismatch"),
                shell.packets());
        assertEquals(2, shell.packets("1").lines().count());
        assertEquals(2, shell.packets("--kind", "rejected").lines().count());
        assertEquals(2, shell.packets("--kind", "SENT").lines().count());
        assertEquals(3, shell.packets("--kind", "good").lines().count());
    }

    @Test
    void eventsShowTheNameOfAnOriginThatIsADevice() {
        events.record(EventKind.DEVICE_EVENT, "amica-movement-0012", "movement detected");
        events.record(EventKind.DEVICE_EVENT, "gone-device", "door opened");
        List<String> lines = shell.events().lines().toList();
        assertTrue(lines.get(1).contains("| amica-movement-0012 \"Movement 0012\" | movement detected"), lines.get(1));
        assertTrue(lines.get(2).contains("| gone-device ") && !lines.get(2).contains("\""), lines.get(2));
    }

    @Test
    void aDeviceFilterThatNamesNoDeviceSaysSoButANodeAddressIsADevice() {
        events.record(EventKind.DEVICE_EVENT, "amica-movement-0012", "movement detected");
        assertTrue(shell.events("--device", "nosuch").startsWith("no device matches 'nosuch' ("),
                shell.events("--device", "nosuch"));
        assertTrue(shell.packets("--device", "nosuch").startsWith("no device matches 'nosuch' ("));
        assertEquals(2, shell.events("--device", "0012").lines().count(), "node address 0012");
        assertEquals("(no events)", shell.events("--device", "0012", "--kind", "PROBLEM"), "a device, no entries");
        events.record(EventKind.DEVICE_REMOVED, "removed-0009", "removed");
        assertEquals(2, shell.events("--device", "removed-0009").lines().count(), "a removed device's UID");
    }

    @Test
    void emptyLogsSaySo() {
        assertEquals("(no events)", shell.log());
        assertEquals("(no packets)", shell.packets());
        events.record(EventKind.STATUS, "x", "y");
        assertEquals("(no events)", shell.events("--kind", "PROBLEM"));
    }

    @Test
    void historyIsFilteredByTimeDeviceAndKindFromTheFiles() {
        persist();
        for (int hour = 0; hour < 5; hour++) { // 11:10 .. 15:10
            events.record(EventKind.DEVICE_EVENT, "amica-movement-0012", "movement at hour " + hour);
            events.record(EventKind.STATUS, "amica-movement-0012", "status at hour " + hour);
            events.record(EventKind.DEVICE_EVENT, "flat-occupancy-1", "flat at hour " + hour);
            packets.record(Direction.RECEIVED, "node 0012 via 127.0.0.1:1", new byte[] {(byte) hour}, "");
            packets.record(Direction.RECEIVED, "node 0013 via 127.0.0.1:1", new byte[] {(byte) hour}, "");
            time.advance(Duration.ofHours(1));
        }
        LogSeams.flush(events);
        // now 16:10: the last 2 h are 14:10 and 15:10 (hours 3 and 4)
        List<String> lines = shell.events("--from", "-2h30m", "--device", "Movement 0012", "--kind", "device_event")
                .lines().toList();
        assertEquals(3, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(1).endsWith("movement at hour 3") && lines.get(2).endsWith("movement at hour 4"),
                String.join("\n", lines));
        String between = shell.events("--from", "2026-11-22T12:00:00Z", "--to", "2026-11-22T13:30", "--device",
                "flat-occupancy-1");
        assertEquals(3, between.lines().count(), between); // 12:10 and 13:10 (local time is UTC in this test)
        // a device with a node address also finds the packets of its node
        String node = shell.packets("--device", "amica-movement-0012", "--from", "-2h30m");
        assertEquals(3, node.lines().count(), node);
        assertTrue(node.lines().skip(1).allMatch(l -> l.contains("node 0012 via")), node);
        // a device removed since is found by the uid the log shows
        events.record(EventKind.DEVICE_REMOVED, "gone-device-1", "removed");
        assertEquals(2, shell.events("--device", "gone-device-1").lines().count());
    }

    @Test
    void damagedStoredLinesAreSkippedWithACount() throws IOException {
        persist();
        events.record(EventKind.STATUS, "a", "one");
        LogSeams.flush(events);
        Path file = LogSeams.files(dir, "events").get(0);
        Files.writeString(file, "not a line\n", StandardOpenOption.APPEND);
        events.record(EventKind.STATUS, "a", "two");
        LogSeams.flush(events);
        List<String> lines = shell.events().lines().toList();
        assertEquals(4, lines.size(), String.join("\n", lines));
        assertEquals("(1 damaged lines skipped)", lines.get(3));
    }

    @Test
    void badArgumentsGetOneLineMessages() {
        assertEquals("the number of lines must be a whole number of at least 1, not '0'",
                assertThrows(IllegalArgumentException.class, () -> shell.log("0")).getMessage());
        assertEquals("unknown option --since; usage: " + HistoryArguments.USAGE,
                assertThrows(IllegalArgumentException.class, () -> shell.events("--since", "-1h")).getMessage());
        // an unknown option last on the line is unknown, not "needs a value"
        assertEquals("unknown option --bogus; usage: " + HistoryArguments.USAGE,
                assertThrows(IllegalArgumentException.class, () -> shell.events("--bogus")).getMessage());
        assertEquals("--from needs a value; usage: " + HistoryArguments.USAGE,
                assertThrows(IllegalArgumentException.class, () -> shell.events("--from")).getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> shell.events("--kind", "MOVEMENT"))
                .getMessage().startsWith("unknown kind 'MOVEMENT' (kinds: DRIVER_ADDED, "));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> shell.packets("--from", "yesterday"))
                .getMessage().startsWith("'yesterday' is not a time"));
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> shell.events("--from", "-1h", "--to", "-2h")).getMessage().contains("is after"));
    }
}
