package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;
import java.util.Set;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;
import net.jqwik.api.statistics.Statistics;

/**
 * {@link AmicaCodec#decode} and {@link AmicaPayloads#decode} fed random and damaged input: nothing but
 * {@link AmicaProtocolException} escapes, every rejection names its reason, what is accepted is exactly one
 * frame (it encodes back to the very same bytes), and damage that the format promises to catch is caught.
 */
class AmicaCodecPropertyTest {

    /** Decodes, failing the property on any exception other than AmicaProtocolException. */
    private static AmicaFrame decodeOrNull(byte[] buf, int off, int len) {
        try {
            return AmicaCodec.decode(buf, off, len);
        } catch (AmicaProtocolException e) {
            assertNotNull(e.reason());
            assertTrue(e.getMessage().startsWith(e.reason().name() + " ("), e.getMessage());
            Statistics.collect(e.reason());
            return null;
        } catch (RuntimeException e) {
            return fail("decode threw " + e + " for " + Hex.of(buf, off, len), e);
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

    @Property(tries = 500)
    void anyBytesAreAFrameThatEncodesBackOrARejection(@ForAll("anyInput") byte[] input,
            @ForAll @IntRange(max = 16) int offset) {
        byte[] buf = new byte[offset + input.length + 3];
        System.arraycopy(input, 0, buf, offset, input.length);
        AmicaFrame frame = decodeOrNull(buf, offset, input.length);
        if (frame != null) {
            Statistics.collect("decoded");
            assertArrayEquals(input, AmicaCodec.encode(frame), "a decoded frame is exactly its input");
        }
    }

    @Provide
    Arbitrary<byte[]> anyInput() {
        return Arbitraries.oneOf(FrameArbitraries.garbage(300), FrameArbitraries.validFrames(),
                FrameArbitraries.damagedFrames());
    }

    @Property(tries = 300)
    void everyValidFrameRoundTrips(@ForAll("frames") AmicaFrame frame) throws AmicaProtocolException {
        byte[] bytes = AmicaCodec.encode(frame);
        assertEquals(AmicaCodec.HEADER_LENGTH + frame.payloadLength(), bytes.length);
        assertEquals(frame, AmicaCodec.decode(bytes, 0, bytes.length));
    }

    @Provide
    Arbitrary<AmicaFrame> frames() {
        return FrameArbitraries.frames(FrameArbitraries.payloads());
    }

    @Property(tries = 500)
    void everySingleBitFlipIsRejectedForTheRuleItBreaks(@ForAll("encoded") byte[] frame,
            @ForAll @IntRange(max = 263 * 8 - 1) int anyBit) {
        int bit = anyBit % (frame.length * 8);
        RejectReason expected = switch (bit / 8) {
            case 1 -> RejectReason.BAD_HEADER;                // H
            case 0, 7 -> RejectReason.LENGTH_MISMATCH;         // S or L
            default -> RejectReason.BAD_CHECKSUM;              // CRC-8 catches every single-bit error
        };
        assertEquals(expected, reasonOf(FrameArbitraries.flip(frame, bit)));
    }

    @Provide
    Arbitrary<byte[]> encoded() {
        return FrameArbitraries.validFrames();
    }

    @Property(tries = 300)
    void everyTruncationIsTruncated(@ForAll("encoded") byte[] frame, @ForAll @IntRange(max = 262) int cut) {
        int n = cut % frame.length;
        assertEquals(RejectReason.TRUNCATED, reasonOf(Arrays.copyOf(frame, n)));
    }

    @Property(tries = 300)
    void bytesAfterAFrameMakeItOversize(@ForAll("encoded") byte[] frame, @ForAll @Size(min = 1, max = 300) byte[] tail) {
        assertEquals(RejectReason.OVERSIZE, reasonOf(FrameArbitraries.concat(frame, tail)));
    }

    @Property(tries = 500)
    void anyPayloadBytesDecodeToTheirRecordOrAreRejectedAsUnknownOrBadValue(@ForAll("payloadInput") byte[] p) {
        try {
            AmicaPayload decoded = AmicaPayloads.decode(p);
            Statistics.collect("decoded");
            assertArrayEquals(p, AmicaPayloads.encode(decoded));
        } catch (AmicaProtocolException e) {
            Statistics.collect(e.reason());
            assertTrue(Set.of(RejectReason.UNKNOWN_PAYLOAD, RejectReason.BAD_VALUE).contains(e.reason()),
                    e.getMessage());
        } catch (RuntimeException e) {
            fail("payload decode threw " + e + " for " + Hex.of(p, 0, p.length), e);
        }
    }

    @Provide
    Arbitrary<byte[]> payloadInput() {
        Arbitrary<byte[]> flipped = FrameArbitraries.tablePayloads().flatMap(p -> Arbitraries
                .integers().between(0, p.length * 8 - 1).map(bit -> FrameArbitraries.flip(p, bit)));
        return Arbitraries.oneOf(FrameArbitraries.tablePayloads(), flipped,
                FrameArbitraries.garbage(20));
    }
}
