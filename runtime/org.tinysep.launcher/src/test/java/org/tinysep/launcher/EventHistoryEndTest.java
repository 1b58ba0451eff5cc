package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The history's end for the banner's signals, read from the event-log files before the framework starts. */
class EventHistoryEndTest {

    @TempDir
    Path home;

    private Path etc() throws Exception {
        return Files.createDirectories(home.resolve("etc"));
    }

    private void events(Path folder, String name, String... lines) throws Exception {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve(name), lines.length == 0 ? "" : String.join("\n", lines) + "\n");
    }

    @Test
    void theNewestLineOfTheNewestFileGivesTheEnd() throws Exception {
        Path log = home.resolve("var/log");
        events(log, "events-00000000000000000001.log", "2026-11-30T05:00:00Z\t1\tSTATUS\to\tm",
                "2026-11-30T05:00:01Z\t2\tPROBLEM\to\tMonitoring reduced: x");
        events(log, "events-00000000000000000003.log", "2026-11-30T05:01:00Z\t3\tSTATUS\to\tm",
                "2026-11-30T05:01:00Z\t41\tSTATUS\to\tmessage\twith a tab");
        events(log, "packets-00000000000000000099.log", "2026-11-30T05:01:00Z\t99\tRECEIVED\to\t00");
        assertEquals(41, EventHistoryEnd.read(etc(), home.resolve("var")));
    }

    @Test
    void anEmptyNewestFileLooksAtTheOneBeforeAndNoHistoryIsZero() throws Exception {
        Path log = home.resolve("var/log");
        assertEquals(0, EventHistoryEnd.read(etc(), home.resolve("var")), "no log folder yet: a first start");
        events(log, "events-00000000000000000001.log", "2026-11-30T05:00:00Z\t7\tSTATUS\to\tm");
        events(log, "events-00000000000000000008.log");
        assertEquals(7, EventHistoryEnd.read(etc(), home.resolve("var")));
    }

    @Test
    void theConfiguredFolderIsReadAndOneWithAVariableIsLeftToTheService() throws Exception {
        Path elsewhere = home.resolve("logs-here");
        events(elsewhere, "events-00000000000000000001.log", "2026-11-30T05:00:00Z\t12\tSTATUS\to\tm");
        Files.writeString(etc().resolve(EventHistoryEnd.RUNTIME_CFG), "logDirectory=" + elsewhere + "\n");
        assertEquals(12, EventHistoryEnd.read(etc(), home.resolve("var")));
        Files.writeString(etc().resolve(EventHistoryEnd.RUNTIME_CFG), "logDirectory=${tinysep.var}/log\n");
        assertEquals(-1, EventHistoryEnd.read(etc(), home.resolve("var")));
    }

    @Test
    void aDamagedLastLineIsLeftToTheService() throws Exception {
        events(home.resolve("var/log"), "events-00000000000000000001.log", "2026-11-30T05:00:00Z\tnot-a-number\tX");
        assertEquals(-1, EventHistoryEnd.read(etc(), home.resolve("var")));
    }

    @Test
    void aLongFileIsReadFromItsEndOnly() throws Exception {
        StringBuilder lines = new StringBuilder();
        for (int i = 1; i <= 5000; i++) { // ~300 KB: more than the tail read
            lines.append("2026-11-30T05:00:00Z\t").append(i).append("\tSTATUS\to\t").append("é".repeat(25)).append('\n');
        }
        Path log = Files.createDirectories(home.resolve("var/log"));
        Files.writeString(log.resolve("events-00000000000000000001.log"), lines);
        assertEquals(5000, EventHistoryEnd.read(etc(), home.resolve("var")));
    }
}
