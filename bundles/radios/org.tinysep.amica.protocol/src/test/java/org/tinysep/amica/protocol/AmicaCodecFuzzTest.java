package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * {@link AmicaCodec#decode} and {@link AmicaPayloads#decode} fed random and damaged input ({@link RandomFrames},
 * fixed seeds, see {@link Fuzz}): nothing but {@link AmicaProtocolException} escapes, every rejection names its
 * reason, what is accepted is exactly one frame (it encodes back to the very same bytes), and damage that the
 * format promises to catch is caught.
 */
class AmicaCodecFuzzTest {

    /** Decodes, failing the case on any exception other than AmicaProtocolException. */
    private static AmicaFrame decodeOrNull(byte[] buf, int off, int len, Set<RejectReason> seen) {
        try {
            return AmicaCodec.decode(buf, off, len);
        } catch (AmicaProtocolException e) {
            assertNotNull(e.reason());
            assertTrue(e.getMessage().startsWith(e.reason().name() + " ("), e.getMessage());
            seen.add(e.reason());
            return null;
        } catch (RuntimeException e) {
            return fail("decode threw " + e + " for " + Hex.of(buf, off, len), e);
        }
    }

    /** What a fuzz run saw: how many inputs decoded, and the reasons that rejected the others. */
    private static final class Outcomes {
        int decoded;
        final Set<RejectReason> reasons = EnumSet.noneOf(RejectReason.class);

        /** Both outcomes were reached, and exactly the {@code expected} reasons, or the run proves less. */
        void assertBoth(Set<RejectReason> expected) {
            assertTrue(decoded > 0, "no input decoded");
            assertEquals(expected, reasons);
        }
    }

    private static RejectReason reasonOf(byte[] bytes) {
        try {
            AmicaCodec.decode(bytes, 0, bytes.length);
            return null;
        } catch (AmicaProtocolException e) {
            return e.reason();
        }
    }

    @Test
    void anyBytesAreAFrameThatEncodesBackOrARejection() {
        Outcomes seen = new Outcomes();
        Fuzz.forAll(101, 500, r -> {
            byte[] input = RandomFrames.anyInput(r);
            int offset = Fuzz.between(r, 0, 16);
            byte[] buf = new byte[offset + input.length + 3];
            System.arraycopy(input, 0, buf, offset, input.length);
            AmicaFrame frame = decodeOrNull(buf, offset, input.length, seen.reasons);
            if (frame != null) {
                seen.decoded++;
                assertArrayEquals(input, AmicaCodec.encode(frame), "a decoded frame is exactly its input");
            }
        });
        // the input must reach both outcomes and every reason decode can give, or the check proves less
        seen.assertBoth(EnumSet.of(RejectReason.TRUNCATED, RejectReason.OVERSIZE, RejectReason.BAD_HEADER,
                RejectReason.LENGTH_MISMATCH, RejectReason.BAD_CHECKSUM));
    }

    @Test
    void everyValidFrameRoundTrips() {
        Fuzz.forAll(102, 300, r -> {
            AmicaFrame frame = RandomFrames.frame(r);
            byte[] bytes = AmicaCodec.encode(frame);
            assertEquals(AmicaCodec.HEADER_LENGTH + frame.payloadLength(), bytes.length);
            assertEquals(frame, AmicaCodec.decode(bytes, 0, bytes.length));
        });
    }

    @Test
    void everySingleBitFlipIsRejectedForTheRuleItBreaks() {
        Fuzz.forAll(103, 500, r -> {
            byte[] frame = RandomFrames.validFrame(r);
            int bit = Fuzz.between(r, 0, frame.length * 8 - 1);
            RejectReason expected = switch (bit / 8) {
                case 1 -> RejectReason.BAD_HEADER;                // H
                case 0, 7 -> RejectReason.LENGTH_MISMATCH;         // S or L
                default -> RejectReason.BAD_CHECKSUM;              // CRC-8 catches every single-bit error
            };
            assertEquals(expected, reasonOf(RandomFrames.flip(frame, bit)), "bit " + bit);
        });
    }

    @Test
    void everyTruncationIsTruncated() {
        Fuzz.forAll(104, 300, r -> {
            byte[] frame = RandomFrames.validFrame(r);
            int n = Fuzz.between(r, 0, frame.length - 1);
            assertEquals(RejectReason.TRUNCATED, reasonOf(Arrays.copyOf(frame, n)), "cut to " + n);
        });
    }

    @Test
    void bytesAfterAFrameMakeItOversize() {
        Fuzz.forAll(105, 300, r -> {
            byte[] frame = RandomFrames.validFrame(r);
            byte[] tail = Fuzz.bytes(r, 1, 300);
            assertEquals(RejectReason.OVERSIZE, reasonOf(RandomFrames.concat(frame, tail)));
        });
    }

    @Test
    void anyPayloadBytesDecodeToTheirRecordOrAreRejectedAsUnknownOrBadValue() {
        Outcomes seen = new Outcomes();
        Fuzz.forAll(106, 700, r -> {
            byte[] table = RandomFrames.tablePayload(r);
            byte[] p = switch (r.nextInt(4)) {
                case 0 -> table;
                case 1 -> RandomFrames.flip(table, r.nextInt(table.length * 8));
                case 2 -> r.nextBoolean() ? RandomFrames.delete(table, r.nextInt(table.length)) // a lost byte
                        : RandomFrames.insert(table, r.nextInt(table.length + 1), Fuzz.anyByte(r)); // one too many
                default -> RandomFrames.garbage(r, 20);
            };
            try {
                AmicaPayload payload = AmicaPayloads.decode(p);
                seen.decoded++;
                assertArrayEquals(p, AmicaPayloads.encode(payload));
            } catch (AmicaProtocolException e) {
                seen.reasons.add(e.reason());
                assertTrue(Set.of(RejectReason.UNKNOWN_PAYLOAD, RejectReason.BAD_VALUE).contains(e.reason()),
                        e.getMessage());
            } catch (RuntimeException e) {
                fail("payload decode threw " + e + " for " + Hex.of(p, 0, p.length), e);
            }
        });
        seen.assertBoth(EnumSet.of(RejectReason.UNKNOWN_PAYLOAD, RejectReason.BAD_VALUE));
    }
}
