package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.protocol.AmicaCodecTest.KEEP_ALIVE_1_17;
import static org.tinysep.amica.protocol.AmicaCodecTest.LIGHT_40_TO_1_20;
import static org.tinysep.amica.protocol.AmicaCodecTest.MOVEMENT_1_17;
import static org.tinysep.amica.protocol.AmicaCodecTest.REED_OPEN_1_18;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.FrameChecks;

class AmicaStreamDecoderTest {

    private final RecordingSink sink = new RecordingSink();
    private final AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);

    private static String frameOf(byte[] bytes) throws AmicaProtocolException {
        return AmicaCodec.decode(bytes, 0, bytes.length).toString();
    }

    private void feed(byte[] bytes) {
        decoder.accept(bytes, 0, bytes.length);
    }

    @Test
    void decodesBackToBackFrames() throws Exception {
        feed(concat(KEEP_ALIVE_1_17, MOVEMENT_1_17, REED_OPEN_1_18));
        assertEquals(List.of(frameOf(KEEP_ALIVE_1_17), frameOf(MOVEMENT_1_17), frameOf(REED_OPEN_1_18)),
                sink.events);
        assertEquals(0, decoder.buffered());
    }

    @Test
    void skipsGarbageBeforeAFrameAndReportsItOnce() throws Exception {
        feed(concat(hex("FF 00 13"), MOVEMENT_1_17));
        assertEquals(List.of("BAD_HEADER 3", frameOf(MOVEMENT_1_17)), sink.events);
    }

    @Test
    void skipsGarbageBetweenFrames() throws Exception {
        feed(concat(MOVEMENT_1_17, hex("AA BB"), REED_OPEN_1_18));
        assertEquals(List.of(frameOf(MOVEMENT_1_17), "BAD_HEADER 2", frameOf(REED_OPEN_1_18)), sink.events);
    }

    @Test
    void frameWithBadChecksumIsSkippedAndTheNextFrameDecoded() throws Exception {
        byte[] bad = LIGHT_40_TO_1_20.clone();
        bad[6] = (byte) 0xD1;
        feed(concat(bad, LIGHT_40_TO_1_20));
        assertEquals(List.of("BAD_CHECKSUM 12", frameOf(LIGHT_40_TO_1_20)), sink.events);
    }

    @Test
    void frameWithALostByteIsSkippedAndTheNextFrameDecoded() throws Exception {
        byte[] lost = Arrays.copyOf(MOVEMENT_1_17, MOVEMENT_1_17.length - 1);
        feed(concat(lost, REED_OPEN_1_18));
        assertEquals(List.of("BAD_CHECKSUM 11", frameOf(REED_OPEN_1_18)), sink.events);
    }

    @Test
    void sizeDifferentFromLengthIsSkipped() throws Exception {
        byte[] mismatch = MOVEMENT_1_17.clone();
        mismatch[7] = 9;
        feed(concat(mismatch, MOVEMENT_1_17));
        assertEquals(List.of("LENGTH_MISMATCH 12", frameOf(MOVEMENT_1_17)), sink.events);
    }

    @Test
    void decodesEmptyPayloadFrames() throws Exception {
        byte[] empty = hex("00 A1 11 00 01 0A 47 00");
        feed(concat(empty, empty));
        assertEquals(List.of(frameOf(empty), frameOf(empty)), sink.events);
    }

    @Test
    void sameResultWhenSplitAtEveryPairOfByteBoundaries() {
        byte[] bad = LIGHT_40_TO_1_20.clone();
        bad[6] = 0;
        byte[] stream = concat(hex("01 A1 02"), KEEP_ALIVE_1_17, hex("FF"), MOVEMENT_1_17, bad, LIGHT_40_TO_1_20,
                REED_OPEN_1_18, hex("00 A1 11 00 01 0A 47 00"));
        feed(stream);
        List<String> expected = List.copyOf(sink.events);
        assertEquals(5, sink.frames);
        // "01 A1" looks like a header and S = L = 1 (the keep-alive's netgroup byte): the CRC rejects it
        assertEquals("BAD_CHECKSUM 3", expected.get(0));
        assertEquals("BAD_CHECKSUM 12", expected.get(4));
        FrameChecks.assertSplitsAlike(stream, expected, () -> {
            RecordingSink r = new RecordingSink();
            return new FrameChecks.Feeding(new AmicaStreamDecoder(r)::accept, () -> r.events);
        });
    }

    @Test
    void decodesMoreFramesInOneCallThanTheBufferHolds() throws Exception {
        int count = 2000;
        byte[][] frames = new byte[count][];
        for (int i = 0; i < count; i++) {
            frames[i] = AmicaCodec.encode(new AmicaFrame(1, 17, 0, i % 256, new byte[] {5, 2, 0, (byte) (i % 101)}));
        }
        feed(concat(frames));
        assertEquals(count, sink.frames);
        assertEquals(frameOf(frames[count - 1]), sink.events.get(count - 1));
        assertEquals(0, sink.skipped);
    }

    @Test
    void bufferStaysBoundedUnderEndlessGarbageAndEveryByteIsAccountedFor() throws Exception {
        long fed = FrameChecks.assertEndlessGarbageStaysBounded(new FrameChecks.Counted(decoder::accept,
                decoder::buffered, () -> sink.frames, () -> sink.skipped, () -> sink.events.size()),
                AmicaCodec.MAX_FRAME, AmicaStreamDecoder.BUFFER_SIZE);

        byte[] padding = new byte[AmicaCodec.MAX_FRAME];
        feed(concat(MOVEMENT_1_17, padding, REED_OPEN_1_18));
        assertEquals(2, sink.frames, "frames after garbage are still decoded");
        assertEquals(fed + padding.length, sink.skipped);
        assertEquals(frameOf(REED_OPEN_1_18), sink.events.get(sink.events.size() - 1));
    }

    @Test
    void longRunsAreReportedInChunksOfTheBufferSize() throws Exception {
        feed(new byte[10_000]);
        assertEquals(List.of("BAD_HEADER 4096", "BAD_HEADER 4096"), sink.events);
        assertEquals(1, decoder.buffered());
        feed(MOVEMENT_1_17);
        assertEquals(List.of("BAD_HEADER 4096", "BAD_HEADER 4096", "BAD_HEADER 1808", frameOf(MOVEMENT_1_17)),
                sink.events);
    }

    @Test
    void resetReportsAnIncompleteFrameAndStartsAfresh() throws Exception {
        feed(Arrays.copyOf(KEEP_ALIVE_1_17, 10));
        assertEquals(10, decoder.buffered());
        decoder.reset();
        assertEquals(List.of("TRUNCATED 10"), sink.events);
        assertEquals(0, decoder.buffered());
        feed(MOVEMENT_1_17);
        assertEquals(List.of("TRUNCATED 10", frameOf(MOVEMENT_1_17)), sink.events);
    }

    @Test
    void resetReportsPendingGarbageAndIncompleteFrameAsOneRun() {
        feed(concat(hex("00 00 00"), Arrays.copyOf(MOVEMENT_1_17, 5)));
        decoder.reset();
        assertEquals(List.of("BAD_HEADER 8"), sink.events);
        decoder.reset();
        assertEquals(1, sink.events.size(), "nothing left to report");
    }

    @Test
    void resetReportsARunLongerThanTheBufferInChunksOfTheBufferSize() {
        // 4095 dropped bytes (one short of a reported chunk), then 10 bytes of an incomplete candidate frame
        feed(concat(new byte[AmicaStreamDecoder.BUFFER_SIZE - 1], Arrays.copyOf(KEEP_ALIVE_1_17, 10)));
        assertEquals(List.of(), sink.events);
        assertEquals(10, decoder.buffered());
        decoder.reset();
        // the run with its reason up to the bound, then the rest of the candidate as a truncated frame
        assertEquals(List.of("BAD_HEADER 4096", "TRUNCATED 9"), sink.events);
        assertEquals(0, decoder.buffered());
        decoder.reset();
        assertEquals(2, sink.events.size(), "nothing left to report");
    }

    @Test
    void rejectsRangesOutsideTheInput() {
        assertThrows(IndexOutOfBoundsException.class, () -> decoder.accept(new byte[4], 2, 3));
        assertThrows(NullPointerException.class, () -> new AmicaStreamDecoder(null));
    }
}
