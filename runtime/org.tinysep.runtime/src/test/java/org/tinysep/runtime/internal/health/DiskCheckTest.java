package org.tinysep.runtime.internal.health;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.runtime.internal.log.EventLogService;

/**
 * Disk nearly full, without filling a disk: the minimum free space is set above what the real disk has free, so the
 * real file store reports "too little". The logs are trimmed first (oldest packet files, then oldest event files,
 * never the file being written), state files are left alone, and one PROBLEM says so in plain words; with enough
 * room again a STATUS says that.
 */
class DiskCheckTest {

    @TempDir
    Path var;
    private final EventLogService events = new EventLogService();

    @Test
    void belowTheMinimumOldLogsGoFirstAndAProblemIsRaisedOnce() throws Exception {
        Path logs = var.resolve("log");
        Files.createDirectories(logs);
        for (long seq : new long[] {1, 1000, 2000}) {
            Files.writeString(logs.resolve(String.format("events-%020d.log", seq)), "x".repeat(1000));
            Files.writeString(logs.resolve(String.format("packets-%020d.log", seq)), "y".repeat(1000));
        }
        Files.writeString(var.resolve("house.xml"), "<HOUSE_ROOMS/>");
        long impossible = Files.getFileStore(var).getTotalSpace() / (1024 * 1024) + 1; // more than the whole disk

        DiskCheck check = new DiskCheck(var, logs, impossible, events);
        assertTrue(check.check(), "still below the minimum");
        assertEquals(List.of("events-00000000000000002000.log", "packets-00000000000000002000.log"),
                names(logs), "only the files being written are left");
        assertTrue(Files.exists(var.resolve("house.xml")), "state files are never trimmed");
        List<EventEntry> problems = problems();
        assertEquals(1, problems.size(), problems.toString());
        String text = problems.get(0).message();
        assertTrue(text.startsWith("the disk holding the state folder " + var + " is nearly full: "), text);
        assertTrue(text.contains("deleted the 4 oldest log files (0.0 MB) to make room, and it is still too little"),
                text);
        assertTrue(text.contains("Free space on this disk soon"), text);

        assertTrue(check.check());
        assertEquals(1, problems().size(), "one PROBLEM per episode, not one per check");
    }

    @Test
    void withRoomEnoughNothingIsDeletedAndRoomAgainIsTold() throws Exception {
        Path logs = var.resolve("log");
        Files.createDirectories(logs);
        Files.writeString(logs.resolve(String.format("events-%020d.log", 1)), "x");
        Files.writeString(logs.resolve(String.format("events-%020d.log", 2)), "x");
        assertFalse(new DiskCheck(var, logs, 1, events).check());
        assertEquals(2, names(logs).size());
        assertTrue(problems().isEmpty());

        // low first, then room again
        DiskCheck check = new DiskCheck(var, logs, Files.getFileStore(var).getTotalSpace() / (1024 * 1024) + 1,
                events);
        assertTrue(check.check());
        assertEquals(1, problems().size());
        check.minimum(1);
        assertFalse(check.check());
        List<EventEntry> status = events.recent(100).stream().filter(e -> e.kind() == EventKind.STATUS).toList();
        assertEquals(1, status.size());
        assertTrue(status.get(0).message().startsWith("the disk holding the state folder " + var
                + " has room again: "), status.toString());
    }

    private List<EventEntry> problems() {
        return events.recent(100).stream().filter(e -> e.kind() == EventKind.PROBLEM).toList();
    }

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
