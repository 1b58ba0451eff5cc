package org.tinysep.link.frame;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.FrameChecks;
import org.tinysep.link.frame.testing.TestBytes;

/**
 * The shared skeleton on its own, with the smallest format there is: S, CK, L, then S payload bytes (the two
 * families test it again through their own formats).
 */
class FrameStreamTest {

    enum Reason { TRUNCATED, OVERSIZE, LENGTH_MISMATCH, BAD_CHECKSUM }

    static final class Toy extends FrameFormat<String, Reason> {
        Toy() {
            // the toy encodes its payload given as hex text
            super(3, 1, Reason.TRUNCATED, Reason.OVERSIZE, Reason.LENGTH_MISMATCH, Reason.BAD_CHECKSUM, TestBytes::hex);
        }

        Toy(Reason[] reasons) {
            super(3, 1, reasons, TestBytes::hex);
        }

        @Override
        protected String frameAt(byte[] buf, int off) {
            return "frame " + Arrays.toString(payload(buf, off));
        }

        /** How often {@link #writeHeader} was asked for; the toy has no header fields of its own. */
        int headersWritten;

        @Override
        protected void writeHeader(String frame, byte[] out) {
            headersWritten++;
            out[1] = 0x55; // CK: overwritten by seal, so the toy's encoding shows that seal comes last
        }
    }

    private static final Toy TOY = new Toy();
    private final List<String> events = new ArrayList<>();
    private final FrameStream<String, Reason> stream =
            new FrameStream<>(TOY, events::add, (r, n) -> events.add(r + " " + n));

    private static byte[] frame(String payload) {
        byte[] p = hex(payload);
        byte[] out = new byte[3 + p.length];
        System.arraycopy(p, 0, out, 3, p.length);
        return TOY.seal(out, p.length);
    }

    private void feed(byte[] bytes) {
        stream.accept(bytes, 0, bytes.length);
    }

    @Test
    void sealWritesSizeLengthAndTheCrcOfEveryOtherByte() {
        byte[] f = frame("01 02");
        assertEquals(2, f[0]);
        assertEquals(2, f[2]);
        byte[] withoutCk = {f[0], f[2], f[3], f[4]};
        assertEquals(Crc8.of(withoutCk, 0, withoutCk.length), f[1] & 0xFF);
        assertNull(TOY.check(f, 0, f.length));
    }

    @Test
    void encodeWritesTheHeaderThePayloadAndSealsLast() {
        int before = TOY.headersWritten;
        byte[] f = TOY.encode("01 02");
        assertEquals(before + 1, TOY.headersWritten, "the family writes its header fields");
        assertArrayEquals(frame("01 02"), f);
        assertEquals("frame [1, 2]", TOY.decode(f, 0, f.length, (r, d) -> new IllegalStateException(r + d)));
        assertArrayEquals(hex("00 00 00"), TOY.encode(""));
        assertEquals(3 + 255, TOY.encode("00 ".repeat(255).trim()).length);
    }

    @Test
    void theSharedReasonsAreTakenByNameFromTheFamilysEnum() {
        Toy byName = new Toy(Reason.values());
        byte[] f = frame("01 02");
        assertEquals(Reason.TRUNCATED, byName.check(f, 0, 2));
        assertEquals(Reason.OVERSIZE, byName.check(concat(f, hex("00")), 0, 6));
        f[2] = 3;
        assertEquals(Reason.LENGTH_MISMATCH, byName.check(f, 0, f.length));
        f[2] = 2;
        f[4] ^= 1;
        assertEquals(Reason.BAD_CHECKSUM, byName.check(f, 0, f.length));
        IllegalArgumentException e =
                assertThrows(IllegalArgumentException.class, () -> new Toy(new Reason[] {Reason.TRUNCATED}));
        assertEquals("the family's reasons have no OVERSIZE", e.getMessage());
    }

    @Test
    void checksInTheSharedOrderWithTheirDetails() {
        byte[] f = frame("01 02");
        assertEquals(Reason.TRUNCATED, TOY.check(f, 0, 2));
        assertEquals("2 bytes, a frame has at least 3", TOY.detail(Reason.TRUNCATED, f, 0, 2));
        assertEquals(Reason.TRUNCATED, TOY.check(f, 0, 4));
        assertEquals(Reason.OVERSIZE, TOY.check(concat(f, hex("00")), 0, 6));
        byte[] mismatch = f.clone();
        mismatch[2] = 3;
        assertEquals(Reason.LENGTH_MISMATCH, TOY.check(mismatch, 0, mismatch.length));
        assertEquals("size identifier 2, payload length 3", TOY.detail(Reason.LENGTH_MISMATCH, mismatch, 0, 5));
        byte[] bad = f.clone();
        bad[4] ^= 1;
        assertEquals(Reason.BAD_CHECKSUM, TOY.check(bad, 0, bad.length));
        assertThrows(IllegalStateException.class, () -> TOY.decode(bad, 0, bad.length,
                (reason, detail) -> new IllegalStateException(reason + ": " + detail)));
    }

    @Test
    void findsFramesAfterGarbageAndReportsEachRunOnce() {
        feed(concat(hex("07 00"), frame("0A"), hex("FF"), frame("")));
        assertEquals(List.of("LENGTH_MISMATCH 2", "frame [10]", "LENGTH_MISMATCH 1", "frame []"), events);
    }

    @Test
    void sameResultWhenSplitAnywhere() {
        byte[] bytes = concat(hex("05 00 07"), frame("01 02 03"), hex("00 01 00"), frame("AA"));
        feed(bytes);
        List<String> expected = List.copyOf(events);
        assertEquals(List.of("LENGTH_MISMATCH 3", "frame [1, 2, 3]", "BAD_CHECKSUM 3", "frame [-86]"), expected);
        FrameChecks.assertSplitsAlike(bytes, expected, () -> {
            List<String> e = new ArrayList<>();
            FrameStream<String, Reason> s = new FrameStream<>(TOY, e::add, (r, n) -> e.add(r + " " + n));
            return new FrameChecks.Feeding(s::accept, () -> e);
        });
    }

    @Test
    void resetReportsAnIncompleteFrameAsTruncated() {
        feed(Arrays.copyOf(frame("01 02 03"), 4));
        assertEquals(4, stream.buffered());
        stream.reset();
        assertEquals(List.of("TRUNCATED 4"), events);
        assertEquals(0, stream.buffered());
    }
}
