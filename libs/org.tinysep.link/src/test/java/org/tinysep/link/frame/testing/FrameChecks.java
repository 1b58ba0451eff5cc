package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Random;
import java.util.function.IntSupplier;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/** Checks both protocol families' tests make of what the families share: the CRC and the stream skeleton. */
public final class FrameChecks {

    /** A family's {@code crc8(bytes, off, len)}. */
    public interface Crc {
        int of(byte[] b, int off, int len);
    }

    /** A family's stream decoder's {@code accept(bytes, off, len)}. */
    public interface Accept {
        void accept(byte[] b, int off, int len);
    }

    /**
     * A fresh stream decoder and what its sink recorded so far.
     *
     * @param decoder the decoder's {@code accept}
     * @param events  the sink's events, e.g. frames' strings and {@code "BAD_CHECKSUM 12"}
     */
    public record Feeding(Accept decoder, Supplier<List<String>> events) {
    }

    private FrameChecks() {
    }

    /** CRC-8/SMBUS: the check value of ASCII "123456789" is 0xF4, of nothing 0; ranges outside fail. */
    public static void assertCheckValue(Crc crc) {
        byte[] ascii = "123456789".getBytes(StandardCharsets.US_ASCII);
        assertEquals(0xF4, crc.of(ascii, 0, ascii.length));
        assertEquals(0x00, crc.of(ascii, 0, 0));
        assertEquals(0xF4, crc.of(TestBytes.concat(new byte[3], ascii), 3, ascii.length));
        assertThrows(IndexOutOfBoundsException.class, () -> crc.of(ascii, 5, 5));
    }

    /** The table-driven CRC equals the bitwise definition (polynomial 0x07, MSB first) on random data. */
    public static void assertMatchesBitwiseDefinition(Crc crc) {
        byte[] data = new byte[1000];
        new Random(7).nextBytes(data);
        for (int len = 0; len <= data.length; len += 37) {
            assertEquals(bitwiseCrc8(data, len), crc.of(data, 0, len), "length " + len);
        }
    }

    private static int bitwiseCrc8(byte[] data, int len) {
        int crc = 0;
        for (int i = 0; i < len; i++) {
            crc ^= data[i] & 0xFF;
            for (int bit = 0; bit < 8; bit++) {
                crc = (crc & 0x80) != 0 ? ((crc << 1) ^ 0x07) & 0xFF : (crc << 1) & 0xFF;
            }
        }
        return crc;
    }

    /**
     * Fed in three calls, split at every pair of byte boundaries, and fed one byte at a time, a fresh decoder
     * reports exactly {@code expected}, what it reported for the stream in one call.
     */
    public static void assertSplitsAlike(byte[] stream, List<String> expected, Supplier<Feeding> fresh) {
        for (int i = 0; i <= stream.length; i++) {
            for (int j = i; j <= stream.length; j++) {
                Feeding f = fresh.get();
                f.decoder().accept(stream, 0, i);
                f.decoder().accept(stream, i, j - i);
                f.decoder().accept(stream, j, stream.length - j);
                assertEquals(expected, f.events().get(), "split at " + i + " and " + j);
            }
        }
        Feeding f = fresh.get();
        for (int i = 0; i < stream.length; i++) {
            f.decoder().accept(stream, i, 1);
        }
        assertEquals(expected, f.events().get(), "one byte at a time");
    }

    /**
     * A decoder and its sink's counters.
     *
     * @param decoder  the decoder's {@code accept}
     * @param buffered the decoder's {@code buffered()}
     * @param frames   frames the sink received
     * @param skipped  bytes the sink was told were dropped
     * @param reports  rejection reports plus frames the sink received
     */
    public record Counted(Accept decoder, IntSupplier buffered, IntSupplier frames, LongSupplier skipped,
            IntSupplier reports) {
    }

    /**
     * Feeds 2000 chunks of random garbage (seed 42): the buffer stays below {@code maxFrame}, no frame appears,
     * every byte is reported as dropped or still buffered or in the run that goes on, and long runs are reported.
     *
     * @return how many bytes were fed
     */
    public static long assertEndlessGarbageStaysBounded(Counted d, int maxFrame, int bufferSize) {
        Random random = new Random(42);
        long fed = 0;
        for (int round = 0; round < 2000; round++) {
            byte[] chunk = new byte[1 + random.nextInt(2000)];
            random.nextBytes(chunk);
            d.decoder().accept(chunk, 0, chunk.length);
            fed += chunk.length;
            assertTrue(d.buffered().getAsInt() < maxFrame, "buffered " + d.buffered().getAsInt());
        }
        assertEquals(0, d.frames().getAsInt(), "random garbage must not yield frames (seed 42)");
        long pending = fed - d.skipped().getAsLong() - d.buffered().getAsInt(); // dropped, not yet reported
        assertTrue(pending >= 0 && pending < bufferSize, "pending " + pending);
        assertTrue(d.reports().getAsInt() >= fed / bufferSize, "long runs are still reported");
        return fed;
    }
}
