package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.PacketEntry;

class LineFormatTest {

    private static final Instant T = Instant.parse("2026-11-22T11:10:00.123456789Z");
    private final EventLines events = new EventLines();
    private final PacketLines packets = new PacketLines();

    @Test
    void anEventLineIsReadableAndExact() {
        EventEntry e = new EventEntry(42, T, EventKind.DEVICE_CREATED, "amica-movement-0012",
                "AmicaMovement \"Movement 0012\" created");
        String line = events.encode(e);
        assertEquals("2026-11-22T11:10:00.123456789Z\t42\tDEVICE_CREATED\tamica-movement-0012\t"
                + "AmicaMovement \"Movement 0012\" created", line);
        assertEquals(e, events.decode(line));
    }

    @Test
    void separatorsLineBreaksAndBackslashesInTextAreEscapedAndRestored() {
        String nasty = "a\tb\nc\r\nd\\e \\n f\u0000g\u001bh é 😀 | ; ,";
        EventEntry e = new EventEntry(1, T, EventKind.PROBLEM, "origin\twith\ttabs", nasty);
        String line = events.encode(e);
        assertFalse(line.contains("\n") || line.contains("\r"), line);
        assertEquals(5, line.split("\t", -1).length, line);
        assertEquals(e, events.decode(line));
    }

    @Test
    void aPacketLineHoldsTheBytesAsHexAndRoundTrips() {
        PacketEntry p = new PacketEntry(7, T, Direction.RECEIVED, "node 1.17 via 127.0.0.1:47001",
                new byte[] {(byte) 0xAA, 1, 0x12, (byte) 0xFF}, "");
        String line = packets.encode(p);
        assertEquals("2026-11-22T11:10:00.123456789Z\t7\tRECEIVED\tnode 1.17 via 127.0.0.1:47001\tAA0112FF\t", line);
        PacketEntry back = packets.decode(line);
        assertArrayEquals(p.bytes(), back.bytes());
        assertEquals(List.of(p.sequence(), p.time(), p.direction(), p.origin(), p.note()),
                List.of(back.sequence(), back.time(), back.direction(), back.origin(), back.note()));
        PacketEntry empty = new PacketEntry(8, T, Direction.SENT, "", new byte[0], "not sent:\tport\nclosed");
        PacketEntry emptyBack = packets.decode(packets.encode(empty));
        assertEquals(0, emptyBack.bytes().length);
        assertEquals("not sent:\tport\nclosed", emptyBack.note());
    }

    @Test
    void randomTextRoundTrips() {
        Random r = new Random(6);
        for (int i = 0; i < 2000; i++) {
            StringBuilder sb = new StringBuilder();
            for (int n = r.nextInt(40); n > 0; n--) {
                sb.append((char) (r.nextBoolean() ? r.nextInt(128) : r.nextInt(0xD7FF)));
            }
            String s = sb.toString();
            assertEquals(s, Escaping.unescape(Escaping.escape(s)));
            byte[] b = new byte[r.nextInt(20)];
            r.nextBytes(b);
            assertArrayEquals(b, Escaping.unhex(Escaping.hex(b)));
        }
    }

    @Test
    void damagedLinesAreRejectedWithIllegalArgumentException() {
        String good = events.encode(new EventEntry(3, T, EventKind.STATUS, "o", "m"));
        for (String bad : List.of("", "garbage", good.substring(0, good.length() - 3).replace("\tm", ""),
                good.replace("STATUS", "NO_SUCH_KIND"), good.replace("\t3\t", "\tx\t"),
                good.replace("\t3\t", "\t0\t"), good.replace("2026-11-22", "2026-13-22"), good + "\textra",
                good.replace("\tm", "\tm\\"), good.replace("\tm", "\tm\\q"), good.replace("\tm", "\t\\u12"))) {
            assertThrows(IllegalArgumentException.class, () -> events.decode(bad), bad);
        }
        String packet = packets.encode(new PacketEntry(3, T, Direction.SENT, "o", new byte[] {1, 2}, ""));
        for (String bad : List.of(packet.replace("0102", "010"), packet.replace("0102", "01G2"),
                packet.replace("SENT", "LOST"))) {
            assertThrows(IllegalArgumentException.class, () -> packets.decode(bad), bad);
        }
    }

    @Test
    void theFastTimeParserAgreesWithInstantParse() {
        Random r = new Random(7);
        for (int i = 0; i < 5000; i++) {
            Instant t = Instant.ofEpochSecond(r.nextLong(-30_000_000_000L, 200_000_000_000L),
                    switch (i % 4) {
                        case 0 -> 0;
                        case 1 -> r.nextInt(1000) * 1_000_000;
                        case 2 -> r.nextInt(1_000_000) * 1000;
                        default -> r.nextInt(1_000_000_000);
                    });
            assertEquals(t, Fields.time(t.toString()), t.toString());
        }
        for (String bad : List.of("2026-13-01T00:00:00Z", "2026-02-30T00:00:00Z",
                "2026-01-01T00:00:00.1234567890Z", "2026-01-01T0a:00:00Z", "2026-01-01")) {
            assertThrows(IllegalArgumentException.class, () -> Fields.time(bad), bad);
        }
    }
}
