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
import org.tinysep.link.frame.testing.StreamDecoderContract;

/** The AmICA rules of the stream decoder; what every family's decoder does is {@link StreamDecoderContract}'s. */
class AmicaStreamDecoderTest extends StreamDecoderContract {

    private final RecordingSink sink = new RecordingSink();
    private final AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);

    private static String frameOf(byte[] bytes) throws AmicaProtocolException {
        return AmicaCodec.decode(bytes, 0, bytes.length).toString();
    }

    private void feed(byte[] bytes) {
        decoder.accept(bytes, 0, bytes.length);
    }

    @Override
    protected Probe fresh() {
        RecordingSink r = new RecordingSink();
        AmicaStreamDecoder d = new AmicaStreamDecoder(r);
        return new Probe(d::accept, d::buffered, d::reset, () -> r.events, () -> r.frames, () -> r.skipped);
    }

    @Override
    protected List<byte[]> samples() {
        return List.of(MOVEMENT_1_17, REED_OPEN_1_18, LIGHT_40_TO_1_20, KEEP_ALIVE_1_17);
    }

    @Override
    protected String text(byte[] frame) throws Exception {
        return frameOf(frame);
    }

    @Override
    protected byte[] numbered(int i) {
        return AmicaCodec.encode(new AmicaFrame(1, 17, 0, i % 256, new byte[] {5, 2, 0, (byte) (i % 101)}));
    }

    @Override
    protected int maxFrame() {
        return AmicaCodec.MAX_FRAME;
    }

    @Override
    protected int checksumIndex() {
        return 6;
    }

    @Override
    protected String zeroRunReason() {
        return "BAD_HEADER";
    }

    @Override
    protected int zerosLeftBuffered() {
        return 1;
    }

    @Override
    protected void newWithNullSink() {
        new AmicaStreamDecoder(null);
    }

    @Override
    protected byte[] trickyGarbage() {
        return hex("01 A1 02"); // looks like a header with S = L = 1: the CRC rejects it
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

}
