package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;
import net.jqwik.api.statistics.Statistics;

/**
 * {@link AmicaStreamDecoder} fed streams of frames, damaged frames and garbage, cut into random reads: it never
 * throws, never buffers more than its bound, accounts for every byte (a frame or a counted, reasoned run), finds
 * exactly what the written-down resynchronisation rule finds ({@link ReferenceScanner}) however the stream is
 * cut, and a valid frame right after garbage is still decoded.
 */
class AmicaStreamDecoderPropertyTest {

    /** Feeds {@code stream} in reads of the given sizes (cycled), checking the bound after each read. */
    private static RecordingSink feed(AmicaStreamDecoder decoder, RecordingSink sink, byte[] stream,
            List<Integer> reads) {
        int off = 0;
        for (int r = 0; off < stream.length; r++) {
            int n = Math.min(stream.length - off, reads.get(r % reads.size()));
            decoder.accept(stream, off, n);
            off += n;
            assertTrue(decoder.buffered() <= AmicaStreamDecoder.BUFFER_SIZE, "buffered " + decoder.buffered());
        }
        return sink;
    }

    @Property(tries = 200)
    void findsWhatTheRuleFindsHoweverTheStreamIsCut(@ForAll("streams") byte[] stream,
            @ForAll @Size(min = 1, max = 8) List<@IntRange(min = 1, max = 600) Integer> reads) {
        RecordingSink sink = new RecordingSink(); // fails on a run outside 1..BUFFER_SIZE
        AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);
        feed(decoder, sink, stream, reads);

        assertEquals(ReferenceScanner.scan(stream), sink.events);
        long frames = sink.events.stream().filter(e -> e.startsWith("AmicaFrame")).count();
        Statistics.collect(frames == 0 ? "no frame" : "frames");

        List<String> before = new ArrayList<>(sink.events);
        decoder.reset(); // reports what was left: now every byte is accounted for
        assertEquals(0, decoder.buffered());
        assertEquals(stream.length, sink.skipped + framedBytes(stream, before),
                "every byte is in a frame or in a reported run");
    }

    /** @return the bytes of the frames found, by re-encoding them */
    private static long framedBytes(byte[] stream, List<String> events) {
        return events.stream().filter(e -> e.startsWith("AmicaFrame"))
                .mapToLong(e -> AmicaCodec.HEADER_LENGTH + payloadLength(e)).sum();
    }

    private static int payloadLength(String frameToString) {
        String hex = frameToString.substring(frameToString.indexOf("payload=") + 8, frameToString.length() - 1);
        return hex.isBlank() ? 0 : hex.trim().split(" ").length;
    }

    @Provide
    Arbitrary<byte[]> streams() {
        return FrameArbitraries.streams(12);
    }

    @Property(tries = 200)
    void aValidFrameRightAfterGarbageIsDecoded(@ForAll("garbageWithoutHeaderValue") byte[] garbage,
            @ForAll("tableFrame") byte[] frame, @ForAll @IntRange(min = 1, max = 300) int read)
            throws AmicaProtocolException {
        RecordingSink sink = new RecordingSink();
        feed(new AmicaStreamDecoder(sink), sink, FrameArbitraries.concat(garbage, frame), List.of(read));

        List<String> expected = new ArrayList<>();
        for (int left = garbage.length; left > 0; left -= AmicaStreamDecoder.BUFFER_SIZE) {
            expected.add("BAD_HEADER " + Math.min(left, AmicaStreamDecoder.BUFFER_SIZE));
        }
        expected.add(AmicaCodec.decode(frame, 0, frame.length).toString());
        assertEquals(expected, sink.events);
    }

    /** Garbage that holds no header value 0xA1, so no candidate frame can start inside it. */
    @Provide
    Arbitrary<byte[]> garbageWithoutHeaderValue() {
        return Arbitraries.bytes().filter(b -> (b & 0xFF) != AmicaCodec.HEADER_VALUE).array(byte[].class)
                .ofMaxSize(9000);
    }

    @Provide
    Arbitrary<byte[]> tableFrame() {
        return FrameArbitraries.tableFrames();
    }

    @Property(tries = 50)
    void endlessGarbageNeverGrowsTheBufferAndIsReportedInBoundedRuns(
            @ForAll @Size(min = 5000, max = 20000) byte[] garbage,
            @ForAll @IntRange(min = 1, max = 5000) int read) {
        RecordingSink sink = new RecordingSink();
        AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);
        feed(decoder, sink, garbage, List.of(read));
        assertTrue(sink.skipped >= garbage.length - AmicaCodec.MAX_FRAME - AmicaStreamDecoder.BUFFER_SIZE,
                "skipped " + sink.skipped + " of " + garbage.length);
    }
}
