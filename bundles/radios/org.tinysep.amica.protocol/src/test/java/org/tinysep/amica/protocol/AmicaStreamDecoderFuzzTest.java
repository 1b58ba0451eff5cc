package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * {@link AmicaStreamDecoder} fed streams of frames, damaged frames and garbage, cut into random reads (fixed seeds,
 * see {@link Fuzz}): it never throws, never buffers more than its bound, reports no run longer than the bound
 * ({@link RecordingSink} fails otherwise), accounts for every byte (a frame or a counted, reasoned run), finds
 * exactly what the written-down resynchronisation rule finds ({@link ReferenceScanner}) however the stream is
 * cut, and a valid frame right after garbage is still decoded.
 */
class AmicaStreamDecoderFuzzTest {

    /** Feeds {@code stream} in reads of the given sizes (cycled), checking the bound after each read. */
    private static void feed(AmicaStreamDecoder decoder, byte[] stream, List<Integer> reads) {
        int off = 0;
        for (int r = 0; off < stream.length; r++) {
            int n = Math.min(stream.length - off, reads.get(r % reads.size()));
            decoder.accept(stream, off, n);
            off += n;
            assertTrue(decoder.buffered() <= AmicaStreamDecoder.BUFFER_SIZE, "buffered " + decoder.buffered());
        }
    }

    /** 1..8 read sizes of 1..max bytes. */
    private static List<Integer> reads(Random r, int max) {
        List<Integer> reads = new ArrayList<>();
        for (int i = Fuzz.between(r, 1, 8); i > 0; i--) {
            reads.add(Fuzz.between(r, 1, max));
        }
        return reads;
    }

    @Test
    void findsWhatTheRuleFindsHoweverTheStreamIsCut() {
        AtomicInteger withFrames = new AtomicInteger();
        Fuzz.forAll(201, 200, r -> {
            byte[] stream = RandomFrames.stream(r, 12);
            RecordingSink sink = new RecordingSink(); // fails on a run outside 1..BUFFER_SIZE
            AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);
            feed(decoder, stream, reads(r, 600));

            assertEquals(ReferenceScanner.scan(stream), sink.events);
            if (sink.frames > 0) {
                withFrames.incrementAndGet();
            }
            assertEveryByteAccountedForAfterReset(decoder, sink, stream.length);
        });
        assertTrue(withFrames.get() > 100, "too few streams with frames: " + withFrames);
    }

    /** Resets the decoder, which reports what was left: then every byte is in a frame or in a reported run. */
    private static void assertEveryByteAccountedForAfterReset(AmicaStreamDecoder decoder, RecordingSink sink,
            long streamLength) {
        List<String> before = new ArrayList<>(sink.events);
        decoder.reset();
        assertEquals(0, decoder.buffered());
        assertEquals(streamLength, sink.skipped + framedBytes(before), "every byte is in a frame or in a reported run");
    }

    /** @return the bytes of the frames found, from their payload lengths */
    private static long framedBytes(List<String> events) {
        return events.stream().filter(e -> e.startsWith("AmicaFrame"))
                .mapToLong(e -> AmicaCodec.HEADER_LENGTH + payloadLength(e)).sum();
    }

    private static int payloadLength(String frameToString) {
        String hex = frameToString.substring(frameToString.indexOf("payload=") + 8, frameToString.length() - 1);
        return hex.isBlank() ? 0 : hex.trim().split(" ").length;
    }

    @Test
    void aValidFrameRightAfterGarbageIsDecoded() {
        Fuzz.forAll(202, 200, r -> {
            byte[] garbage = garbageWithoutHeaderValue(r, 9000);
            byte[] frame = RandomFrames.tableFrame(r);
            RecordingSink sink = new RecordingSink();
            feed(new AmicaStreamDecoder(sink), RandomFrames.concat(garbage, frame), List.of(Fuzz.between(r, 1, 300)));

            List<String> expected = new ArrayList<>();
            for (int left = garbage.length; left > 0; left -= AmicaStreamDecoder.BUFFER_SIZE) {
                expected.add("BAD_HEADER " + Math.min(left, AmicaStreamDecoder.BUFFER_SIZE));
            }
            expected.add(AmicaCodec.decode(frame, 0, frame.length).toString());
            assertEquals(expected, sink.events);
        });
    }

    /** 0..maxSize bytes that hold no header value 0xA1, so no candidate frame can start inside them. */
    private static byte[] garbageWithoutHeaderValue(Random r, int maxSize) {
        byte[] garbage = RandomFrames.garbage(r, maxSize);
        for (int i = 0; i < garbage.length; i++) {
            while ((garbage[i] & 0xFF) == AmicaCodec.HEADER_VALUE) {
                garbage[i] = Fuzz.anyByte(r);
            }
        }
        return garbage;
    }

    @Test
    void endlessGarbageNeverGrowsTheBufferAndIsReportedInBoundedRuns() {
        Fuzz.forAll(203, 50, r -> {
            byte[] garbage = Fuzz.bytes(r, 5000, 20000);
            RecordingSink sink = new RecordingSink();
            AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);
            feed(decoder, garbage, List.of(Fuzz.between(r, 1, 5000)));
            assertTrue(sink.skipped >= garbage.length - AmicaCodec.MAX_FRAME - AmicaStreamDecoder.BUFFER_SIZE,
                    "skipped " + sink.skipped + " of " + garbage.length);
            assertEveryByteAccountedForAfterReset(decoder, sink, garbage.length);
        });
    }

    @Test
    void resetAfterALongRunAndAnIncompleteCandidateReportsBoundedRuns() {
        Fuzz.forAll(204, 200, r -> {
            // zeros (a BAD_HEADER run) up to just short of the bound, then an incomplete frame: what reset()
            // reports, the run plus the candidate, may cross the bound
            byte[] zeros = new byte[Fuzz.between(r, 1, AmicaStreamDecoder.BUFFER_SIZE - 1)];
            byte[] frame = RandomFrames.validFrame(r);
            byte[] stream = RandomFrames.concat(zeros, Arrays.copyOf(frame, Fuzz.between(r, 0, frame.length - 1)));
            RecordingSink sink = new RecordingSink(); // fails on a run outside 1..BUFFER_SIZE
            AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);
            feed(decoder, stream, reads(r, 600));
            assertEveryByteAccountedForAfterReset(decoder, sink, stream.length);
        });
    }
}
