package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.From;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;

/**
 * Property-based tests of the decoders with random and mutated input: nothing but
 * {@link SunSpotProtocolException} ever leaves a decoder, the stream decoder never throws, never exceeds its bound
 * and accounts for every byte, and a valid frame is found after any garbage.
 */
class SunSpotDecoderPropertiesTest {

    /** Random frames of the four known sensor types with random (not necessarily valid) payload contents. */
    @Provide
    Arbitrary<byte[]> validFrames() {
        Arbitrary<Long> address = Arbitraries.longs();
        Arbitrary<Integer> type = Arbitraries.integers().between(2, 5);
        Arbitrary<byte[]> rest = Arbitraries.bytes().array(byte[].class).ofMaxSize(SunSpotCodec.MAX_PAYLOAD - 1);
        return Combinators.combine(address, type, rest).as((a, t, r) -> {
            byte[] payload = new byte[r.length + 1];
            payload[0] = (byte) (int) t;
            System.arraycopy(r, 0, payload, 1, r.length);
            return SunSpotCodec.encode(SunSpotFrame.of(new SunSpotAddress(a), payload));
        });
    }

    @Provide
    Arbitrary<byte[]> garbage() {
        return Arbitraries.bytes().array(byte[].class).ofMaxSize(3000);
    }

    @Property(tries = 2000)
    void decodeOfRandomBytesThrowsOnlyProtocolExceptions(@ForAll @Size(max = 300) byte[] bytes) {
        try {
            SunSpotFrame f = SunSpotCodec.decode(bytes, 0, bytes.length);
            assertArrayEquals(bytes, SunSpotCodec.encode(f), "a decoded frame re-encodes to its bytes");
        } catch (SunSpotProtocolException e) {
            assertReasonAndMessage(e);
        }
    }

    @Property(tries = 2000)
    void decodeOfMutatedFramesThrowsOnlyProtocolExceptions(@ForAll("validFrames") byte[] frame,
            @ForAll @IntRange(max = 3) int mutation, @ForAll @IntRange(max = 10_000) int where,
            @ForAll byte value) {
        byte[] mutated = mutate(frame, mutation, where % (frame.length + 1), value);
        try {
            SunSpotFrame f = SunSpotCodec.decode(mutated, 0, mutated.length);
            assertArrayEquals(mutated, SunSpotCodec.encode(f), "a decoded frame re-encodes to its bytes");
            try {
                SunSpotPayload p = SunSpotPayloads.decode(f.payload());
                assertArrayEquals(f.payload(), SunSpotPayloads.encode(p), "a decoded payload re-encodes");
            } catch (SunSpotProtocolException e) {
                assertReasonAndMessage(e);
            }
        } catch (SunSpotProtocolException e) {
            assertReasonAndMessage(e);
        }
    }

    @Property(tries = 1000)
    void everySingleBitFlipIsRejected(@ForAll("validFrames") byte[] frame, @ForAll @IntRange(max = 100_000) int bit) {
        byte[] flipped = frame.clone();
        int b = bit % (frame.length * 8);
        flipped[b / 8] ^= (byte) (1 << (b % 8));
        SunSpotProtocolException e = assertThrows(SunSpotProtocolException.class,
                () -> SunSpotCodec.decode(flipped, 0, flipped.length));
        assertReasonAndMessage(e);
    }

    @Property(tries = 2000)
    void payloadDecodeOfRandomBytesIsCanonicalOrAProtocolException(@ForAll @Size(max = 20) byte[] payload) {
        try {
            SunSpotPayload p = SunSpotPayloads.decode(payload);
            assertArrayEquals(payload, SunSpotPayloads.encode(p));
        } catch (SunSpotProtocolException e) {
            assertReasonAndMessage(e);
        }
    }

    @Property(tries = 500)
    void streamDecoderNeverThrowsStaysBoundedAndAccountsForEveryByte(@ForAll("garbage") byte[] garbage,
            @ForAll("validFrames") byte[] frame, @ForAll @IntRange(min = 1, max = 600) int chunk) {
        RecordingSink sink = new RecordingSink();
        SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);
        byte[] stream = TestBytes.concat(garbage, frame, new byte[SunSpotCodec.MAX_FRAME], garbage, frame);
        for (int off = 0; off < stream.length; off += chunk) {
            decoder.accept(stream, off, Math.min(chunk, stream.length - off));
            assertTrue(decoder.buffered() <= SunSpotStreamDecoder.BUFFER_SIZE);
            assertTrue(decoder.buffered() < SunSpotCodec.MAX_FRAME, "only an incomplete candidate waits");
        }
        decoder.reset();
        assertEquals(0, decoder.buffered());
        assertNull(sink.badRun, "every rejection has a reason and 1..4096 bytes");
        long frameBytes = sink.frameList.stream().mapToLong(f -> SunSpotCodec.HEADER_LENGTH + f.payloadLength()).sum();
        assertEquals(stream.length, sink.skipped + frameBytes, "every byte is a frame's or reported as skipped");
    }

    @Property(tries = 500)
    void validFrameAfterGarbageIsDecoded(@ForAll("garbage") byte[] garbage, @ForAll("validFrames") byte[] frame)
            throws SunSpotProtocolException {
        RecordingSink sink = new RecordingSink();
        SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);
        // zeros cannot start a frame (sensor type 0), and 267 of them complete any candidate begun in the garbage
        byte[] stream = TestBytes.concat(garbage, frame, new byte[SunSpotCodec.MAX_FRAME]);
        decoder.accept(stream, 0, stream.length);
        SunSpotFrame expected = SunSpotCodec.decode(frame, 0, frame.length);
        assertTrue(sink.frameList.contains(expected), "frame after " + garbage.length + " bytes of garbage lost");
        assertEquals(expected, sink.frameList.get(sink.frameList.size() - 1));
    }

    @Property(tries = 200)
    void backToBackValidFramesAreAllDecodedInOrder(@ForAll @Size(max = 40) List<@From("validFrames") byte[]> frames,
            @ForAll @IntRange(min = 1, max = 300) int chunk) throws SunSpotProtocolException {
        RecordingSink sink = new RecordingSink();
        SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);
        byte[] stream = TestBytes.concat(frames.toArray(new byte[0][]));
        for (int off = 0; off < stream.length; off += chunk) {
            decoder.accept(stream, off, Math.min(chunk, stream.length - off));
        }
        assertEquals(frames.size(), sink.frames);
        assertEquals(0, sink.skipped);
        for (int i = 0; i < frames.size(); i++) {
            byte[] f = frames.get(i);
            assertEquals(SunSpotCodec.decode(f, 0, f.length), sink.frameList.get(i));
        }
    }

    private static byte[] mutate(byte[] frame, int mutation, int at, byte value) {
        switch (mutation) {
            case 0: { // overwrite one byte
                byte[] b = frame.clone();
                b[Math.min(at, b.length - 1)] = value;
                return b;
            }
            case 1: { // drop one byte
                int i = Math.min(at, frame.length - 1);
                byte[] b = new byte[frame.length - 1];
                System.arraycopy(frame, 0, b, 0, i);
                System.arraycopy(frame, i + 1, b, i, frame.length - i - 1);
                return b;
            }
            case 2: { // insert one byte
                byte[] b = new byte[frame.length + 1];
                System.arraycopy(frame, 0, b, 0, at);
                b[at] = value;
                System.arraycopy(frame, at, b, at + 1, frame.length - at);
                return b;
            }
            default: // truncate
                return java.util.Arrays.copyOf(frame, at);
        }
    }

    private static void assertReasonAndMessage(SunSpotProtocolException e) {
        assertTrue(e.reason() != null && e.getMessage().startsWith(e.reason().name()), e.getMessage());
    }
}
