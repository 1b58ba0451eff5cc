package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.device.support.testing.MutableClock;

/** The log services keep their history across a restart (a new service object on the same folder). */
class LogServicesHistoryTest {

    @TempDir
    Path dir;

    private final MutableClock clock = new MutableClock(Instant.parse("2026-11-22T10:00:00Z"));

    private EventLogService events(int capacity) {
        EventLogService log = new EventLogService(clock);
        log.configure(() -> capacity);
        log.persist(LogSettings.in(dir));
        log.start(() -> capacity, Runnable::run, e -> { });
        return log;
    }

    @Test
    void aRestartedEventLogShowsTheEntriesFromBeforeAndNumberingGoesOn() {
        EventLogService first = events(100);
        for (int i = 1; i <= 150; i++) {
            first.record(EventKind.DEVICE_EVENT, "door-" + i, "door opened\nline two");
            clock.advance(Duration.ofSeconds(1));
            if (i % 50 == 0) {
                first.persistent().flush(); // a burst bigger than the ring could outrun the writer (docs/logs.md)
            }
        }
        first.persist(null); // deactivation: written, forced, closed

        EventLogService second = events(100);
        List<EventEntry> recent = second.recent(1000);
        assertEquals(100, recent.size(), "the ring is full of history");
        assertEquals(51, recent.get(0).sequence());
        assertEquals("door opened\nline two", recent.get(99).message());
        second.record(EventKind.STATUS, "x", "after restart");
        assertEquals(151, second.recent(1).get(0).sequence());
        assertEquals(151, second.query(LogQuery.newest(1000)).matched(), "files reach beyond the ring");
        second.persist(null);
    }

    /** Issue 10 item 6: the event log holds alert texts; its folder and files are private to the owner. */
    @Test
    void logFilesAndTheirFolderArePrivateToTheOwner() throws IOException {
        Path folder = dir.resolve("var/log"); // not the test's own temp folder, which is private already
        EventLogService log = new EventLogService(clock);
        log.configure(() -> 10);
        log.persist(LogSettings.in(folder));
        log.start(() -> 10, Runnable::run, e -> { });
        log.record(EventKind.PROBLEM, "Inactivity", "no activity in Bathroom since 14:01");
        log.persist(null);
        Path file = new LogFolder(folder, "events").files().get(0);
        assertEquals("rw-------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(file)), file.toString());
        assertEquals("rwx------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(file.getParent())), file.getParent().toString());
    }

    @Test
    void damagedLinesFoundOnStartAreReportedInTheEventLog() throws IOException {
        EventLogService first = events(10);
        first.record(EventKind.STATUS, "a", "one");
        first.persist(null);
        Path file = new LogFolder(dir, "events").files().get(0);
        Files.writeString(file, "garbage\nmore garbage\n", StandardOpenOption.APPEND);

        EventLogService second = events(10);
        EventEntry last = second.recent(1).get(0);
        assertEquals(EventKind.PROBLEM, last.kind());
        assertEquals("2 damaged lines in the event-log files were skipped", last.message());
        assertEquals(2, last.sequence());
        second.persist(null);
    }

    @Test
    void thePacketLogReloadsItsBytes() {
        PacketLogService first = new PacketLogService(clock);
        first.persist(LogSettings.in(dir));
        first.record(Direction.RECEIVED, "node 1.17 via 127.0.0.1:1", new byte[] {4, (byte) 161, 0, (byte) 255}, "");
        first.record(Direction.SENT, "node 1.17", new byte[0], "not sent: port closed");
        first.deactivate();

        PacketLogService second = new PacketLogService(clock);
        second.persist(LogSettings.in(dir));
        List<PacketEntry> back = second.recent(10);
        assertEquals(2, back.size());
        assertArrayEquals(new byte[] {4, (byte) 161, 0, (byte) 255}, back.get(0).bytes());
        assertEquals("not sent: port closed", back.get(1).note());
        second.deactivate();
    }

    @Test
    void newSettingsReopenTheFilesWithoutReloadingAndMemoryOnlyWritesNothing() throws IOException {
        EventLogService log = events(100);
        log.record(EventKind.STATUS, "a", "one");
        Path other = dir.resolve("other");
        log.persist(new LogSettings(other, 4096, 3, Duration.ZERO, Duration.ofMillis(100)));
        log.record(EventKind.STATUS, "a", "two");
        log.persistent().flush();
        assertEquals(2, log.recent(10).size(), "not reloaded: nothing doubled");
        List<String> lines = Files.readAllLines(new LogFolder(other, "events").files().get(0));
        assertEquals(1, lines.size());
        assertTrue(lines.get(0).endsWith("\ttwo"), lines.get(0));

        log.persist(null);
        assertNull(log.persistent());
        log.record(EventKind.STATUS, "a", "three");
        assertEquals(3, log.query(LogQuery.newest(10)).matched(), "memory only: the ring is searched");
        assertEquals(1, Files.readAllLines(new LogFolder(other, "events").files().get(0)).size());
    }
}
