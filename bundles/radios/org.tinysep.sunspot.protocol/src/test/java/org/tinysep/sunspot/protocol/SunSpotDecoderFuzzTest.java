package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.Fuzz;
import org.tinysep.link.frame.testing.TestBytes;

/**
 * The decoders fed random and mutated input (fixed seeds, see {@link Fuzz}): nothing but
 * {@link SunSpotProtocolException} ever leaves a decoder, the stream decoder never throws, never exceeds its bound
 * and accounts for every byte, and a valid frame is found after any garbage.
 */
class SunSpotDecoderFuzzTest {

    /** A random frame of one of the four known sensor types with random (not necessarily valid) payload contents. */
    private static byte[] validFrame(Random r) {
        byte[] rest = Fuzz.bytes(r, SunSpotCodec.MAX_PAYLOAD - 1);
        byte[] payload = new byte[rest.length + 1];
        payload[0] = (byte) Fuzz.between(r, 2, 5);
        System.arraycopy(rest, 0, payload, 1, rest.length);
        return SunSpotCodec.encode(SunSpotFrame.of(new SunSpotAddress(Fuzz.anyLong(r)), payload));
    }

    /** @return the frame {@code bytes} decode to, which re-encodes to them, or empty if they are rejected */
    private static Optional<SunSpotFrame> decodedOrRejected(byte[] bytes) {
        try {
            SunSpotFrame f = SunSpotCodec.decode(bytes, 0, bytes.length);
            assertArrayEquals(bytes, SunSpotCodec.encode(f), "a decoded frame re-encodes to its bytes");
            return Optional.of(f);
        } catch (SunSpotProtocolException e) {
            assertReasonAndMessage(e);
            return Optional.empty();
        }
    }

    /** A payload decodes and re-encodes to its bytes, or is rejected with a reason and a message. */
    private static void payloadDecodedOrRejected(byte[] payload) {
        try {
            SunSpotPayload p = SunSpotPayloads.decode(payload);
            assertArrayEquals(payload, SunSpotPayloads.encode(p), "a decoded payload re-encodes");
        } catch (SunSpotProtocolException e) {
            assertReasonAndMessage(e);
        }
    }

    /** A valid frame with one random mutation (see {@code mutate}). */
    private static byte[] mutatedFrame(Random r) {
        byte[] frame = validFrame(r);
        return mutate(frame, r.nextInt(4), Fuzz.between(r, 0, frame.length), Fuzz.anyByte(r));
    }

    private static byte[] garbage(Random r) {
        return Fuzz.bytes(r, 3000);
    }

    @Test
    void decodeOfRandomBytesThrowsOnlyProtocolExceptions() {
        Fuzz.forAll(401, 2000, r -> decodedOrRejected(Fuzz.bytes(r, 300)));
    }

    @Test
    void decodeOfMutatedFramesThrowsOnlyProtocolExceptions() {
        Fuzz.forAll(402, 2000,
                r -> decodedOrRejected(mutatedFrame(r)).ifPresent(f -> payloadDecodedOrRejected(f.payload())));
    }

    @Test
    void everySingleBitFlipIsRejected() {
        Fuzz.forAll(403, 1000, r -> {
            byte[] frame = validFrame(r);
            byte[] flipped = frame.clone();
            int b = Fuzz.between(r, 0, frame.length * 8 - 1);
            flipped[b / 8] ^= (byte) (1 << (b % 8));
            SunSpotProtocolException e = assertThrows(SunSpotProtocolException.class,
                    () -> SunSpotCodec.decode(flipped, 0, flipped.length), "bit " + b);
            assertReasonAndMessage(e);
        });
    }

    @Test
    void payloadDecodeOfRandomBytesIsCanonicalOrAProtocolException() {
        Fuzz.forAll(404, 2000, r -> payloadDecodedOrRejected(Fuzz.bytes(r, 20)));
    }

    @Test
    void streamDecoderNeverThrowsStaysBoundedAndAccountsForEveryByte() {
        Fuzz.forAll(405, 500, r -> {
            byte[] garbage = garbage(r);
            byte[] frame = validFrame(r);
            int chunk = Fuzz.between(r, 1, 600);
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
            long frameBytes = sink.frameList.stream()
                    .mapToLong(f -> SunSpotCodec.HEADER_LENGTH + f.payloadLength()).sum();
            assertEquals(stream.length, sink.skipped + frameBytes, "every byte is a frame's or reported as skipped");
        });
    }

    @Test
    void validFrameAfterGarbageIsDecoded() {
        Fuzz.forAll(406, 500, r -> {
            byte[] garbage = garbage(r);
            byte[] frame = validFrame(r);
            RecordingSink sink = new RecordingSink();
            SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);
            // zeros cannot start a frame (sensor type 0), and 267 of them complete any candidate begun in the garbage
            byte[] stream = TestBytes.concat(garbage, frame, new byte[SunSpotCodec.MAX_FRAME]);
            decoder.accept(stream, 0, stream.length);
            SunSpotFrame expected = SunSpotCodec.decode(frame, 0, frame.length);
            assertTrue(sink.frameList.contains(expected), "frame after " + garbage.length + " bytes of garbage lost");
            assertEquals(expected, sink.frameList.get(sink.frameList.size() - 1));
        });
    }

    @Test
    void backToBackValidFramesAreAllDecodedInOrder() {
        Fuzz.forAll(407, 200, r -> {
            byte[][] frames = new byte[Fuzz.between(r, 0, 40)][];
            for (int i = 0; i < frames.length; i++) {
                frames[i] = validFrame(r);
            }
            int chunk = Fuzz.between(r, 1, 300);
            RecordingSink sink = new RecordingSink();
            SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);
            byte[] stream = TestBytes.concat(frames);
            for (int off = 0; off < stream.length; off += chunk) {
                decoder.accept(stream, off, Math.min(chunk, stream.length - off));
            }
            assertEquals(frames.length, sink.frames);
            assertEquals(0, sink.skipped);
            for (int i = 0; i < frames.length; i++) {
                assertEquals(SunSpotCodec.decode(frames[i], 0, frames[i].length), sink.frameList.get(i));
            }
        });
    }

    /** One damage at {@code at} (0..length): 0 overwrite a byte, 1 drop a byte, 2 insert a byte, 3 truncate. */
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
                return Arrays.copyOf(frame, at);
        }
    }

    private static void assertReasonAndMessage(SunSpotProtocolException e) {
        assertTrue(e.reason() != null && e.getMessage().startsWith(e.reason().name()), e.getMessage());
    }
}
