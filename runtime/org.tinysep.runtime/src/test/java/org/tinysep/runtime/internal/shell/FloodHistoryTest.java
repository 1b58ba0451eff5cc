package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.testing.MutableClock;
import org.tinysep.runtime.internal.directory.Home;
import org.tinysep.runtime.internal.log.EventLogService;
import org.tinysep.runtime.internal.log.LogSeams;
import org.tinysep.runtime.internal.log.PacketLogService;

/**
 * Issue 25, item 6: a flood of valid frames from some nodes cannot rotate the history of the others away. The
 * packet history is capped at 2 files of 4 KiB (~60 lines); node 0012 sends 20 frames, then nodes 1.1 .. 1.25
 * send 5,000, from ever-changing ports; {@code tinysep:packets --device 0012} still shows node 0012's 20 frames,
 * also after a restart. The share itself: {@code OriginShareTest}.
 */
class FloodHistoryTest {

    @TempDir
    Path dir;

    private final Home home = new Home();
    private final MutableClock time = new MutableClock(Instant.parse("2026-11-22T11:10:00Z"));
    private PacketLogService packets = LogSeams.packets(time, 100);

    @AfterEach
    void close() {
        LogSeams.close(packets);
    }

    private PacketLogService open() {
        PacketLogService log = LogSeams.packets(time, 100);
        LogSeams.keepIn(log, dir, 4096, 2, Duration.ofMillis(50));
        return log;
    }

    private String shell(String... args) {
        return new HistoryCommands(home.directory, LogSeams.events(time, 100), packets, time).packets(args);
    }

    @Test
    void aFloodFromOtherNodesLeavesANodesNewestFramesInTheHistory() throws IOException {
        packets = open();
        for (int i = 0; i < 20; i++) {
            packets.record(Direction.RECEIVED, "node 0012 via 127.0.0.1:40000", new byte[] {4, (byte) i}, "");
        }
        LogSeams.flush(packets);
        for (int i = 0; i < 5000; i++) {
            packets.record(Direction.RECEIVED, "node 1." + (1 + i % 25) + " via 127.0.0.1:" + (41000 + i),
                    new byte[] {4, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, "");
            if (i % 50 == 49) {
                LogSeams.flush(packets);
            }
        }
        LogSeams.flush(packets);
        List<Path> files = LogSeams.files(dir, "packets");
        assertEquals(2, files.size(), "the history is at its cap");
        assertTrue(Files.readAllLines(files.get(0)).stream().noneMatch(l -> l.contains("node 0012")),
                "the files holding node 0012's frames were rotated away");

        assertNodeFrames(shell("--device", "0012"));
        assertEquals(21, shell("--device", "0012", "--limit", "100").lines().count(), "no doubles");
        String flooder = shell("--device", "node 1.7", "--limit", "1000");
        assertTrue(flooder.lines().count() - 1 >= 20, "a flooding node keeps its share too");

        LogSeams.close(packets);
        packets = open();
        assertNodeFrames(shell("--device", "0012"));
    }

    private static void assertNodeFrames(String table) {
        List<String> lines = table.lines().toList();
        assertEquals(21, lines.size(), table);
        assertTrue(lines.get(1).contains("4 0 ") && lines.get(20).contains("4 19 "), table);
        assertTrue(lines.stream().skip(1).allMatch(l -> l.contains("node 0012 via")), table);
    }
}
