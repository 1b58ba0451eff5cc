package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.time.Instant;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.PacketEntry;

/**
 * The log writer formats every line (thousands of packets a second): its time is written as {@link Instant#toString()}
 * does, exactly, without a {@code DateTimeFormatter} per line, and a packet line costs a bounded number of bytes
 * of garbage (heap allocated by the writer thread per line, {@code com.sun.management.ThreadMXBean}).
 */
class LineCostTest {

    private static final byte[] MOTION = {4, (byte) 161, 17, 0, 1, 1, (byte) 244, 4, 100, 5, 0, 1};

    @Test
    void timesAreWrittenExactlyAsInstantToStringDoes() {
        LogTime times = new LogTime();
        Random r = new Random(29);
        Instant[] edges = {Instant.EPOCH, Instant.parse("2026-11-22T11:10:00Z"), Instant.parse("2026-11-22T11:10:00.1Z"),
                Instant.parse("2026-11-22T11:10:00.000001Z"), Instant.parse("2026-11-22T11:10:00.000000001Z"),
                Instant.parse("2026-11-22T11:10:00.120Z"), Instant.parse("2026-11-22T11:10:00.000120Z"),
                Instant.parse("+10000-01-01T00:00:00.5Z"), Instant.parse("1969-12-31T23:59:59.999999999Z"),
                Instant.MIN, Instant.MAX};
        for (Instant t : edges) {
            assertEquals(t.toString(), times.append(new StringBuilder(), t).toString());
        }
        Instant t = Instant.parse("2026-11-29T16:00:00Z");
        for (int i = 0; i < 100_000; i++) { // same second many times, then the next: the cache must follow
            t = t.plusNanos(r.nextInt(4) == 0 ? 1_000_000L * r.nextInt(700) : r.nextInt(3) == 0 ? 1_000 : 37);
            assertEquals(t.toString(), times.append(new StringBuilder(), t).toString());
        }
    }

    @Test
    void aPacketLineCostsLittleGarbage() {
        PacketLines packets = new PacketLines();
        EventLines events = new EventLines();
        Instant t = Instant.parse("2026-11-29T16:00:00.123456789Z");
        int n = 20_000;
        PacketEntry[] entries = new PacketEntry[n];
        for (int i = 0; i < n; i++) {
            entries[i] = new PacketEntry(i + 1, t.plusNanos(70_123L * i), Direction.RECEIVED,
                    "node 1.17 via 127.0.0.1:44777", MOTION, "");
        }
        long chars = 0;
        for (PacketEntry e : entries) { // warm up
            chars += packets.encode(e).length();
        }
        long before = allocated();
        for (PacketEntry e : entries) {
            chars += packets.encode(e).length();
        }
        long perLine = (allocated() - before) / n;
        assertTrue(chars > 0);
        // the line itself is ~80 bytes; Instant.toString() alone allocated several hundred more per line
        assertTrue(perLine < 400, "bytes allocated per packet line: " + perLine);
        EventEntry e = new EventEntry(7, t, EventKind.DEVICE_CREATED, "amica", "created");
        assertEquals(t + "\t7\tDEVICE_CREATED\tamica\tcreated", events.encode(e));
    }

    private static long allocated() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean()).getCurrentThreadAllocatedBytes();
    }
}
