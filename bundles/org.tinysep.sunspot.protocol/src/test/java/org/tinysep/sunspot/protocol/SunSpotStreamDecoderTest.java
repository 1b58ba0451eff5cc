package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.protocol.SunSpotCodecTest.LIGHT_9ABC;
import static org.tinysep.sunspot.protocol.SunSpotCodecTest.MOVEMENT_1234;
import static org.tinysep.sunspot.protocol.SunSpotCodecTest.MOVEMENT_V2_1234;
import static org.tinysep.sunspot.protocol.SunSpotCodecTest.SPOT_1234;
import static org.tinysep.sunspot.protocol.SunSpotCodecTest.TEMPERATURE_5678;
import static org.tinysep.link.frame.testing.TestBytes.concat;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.FrameChecks;

class SunSpotStreamDecoderTest {

    private final RecordingSink sink = new RecordingSink();
    private final SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);

    private static String frameOf(byte[] bytes) throws SunSpotProtocolException {
        return SunSpotCodec.decode(bytes, 0, bytes.length).toString();
    }

    private void feed(byte[] bytes) {
        decoder.accept(bytes, 0, bytes.length);
    }

    @Test
    void decodesBackToBackFrames() throws Exception {
        feed(concat(MOVEMENT_1234, TEMPERATURE_5678, MOVEMENT_V2_1234, LIGHT_9ABC));
        assertEquals(List.of(frameOf(MOVEMENT_1234), frameOf(TEMPERATURE_5678), frameOf(MOVEMENT_V2_1234),
                frameOf(LIGHT_9ABC)), sink.events);
        assertEquals(0, decoder.buffered());
    }

    @Test
    void skipsGarbageBeforeAFrameAndReportsItOnce() throws Exception {
        // "FF" as S differs from L; the next starts see L = 0x12, 0x34, 0x02 ... none equals its S
        feed(concat(hex("FF 00 13"), MOVEMENT_1234));
        assertEquals(List.of("LENGTH_MISMATCH 3", frameOf(MOVEMENT_1234)), sink.events);
    }

    @Test
    void candidateWithAnUnknownSensorTypeIsDropped() throws Exception {
        byte[] type9 = SunSpotCodec.encode(SunSpotFrame.of(SPOT_1234, hex("09 01 00 01")));
        feed(concat(type9, LIGHT_9ABC));
        assertEquals(List.of("UNKNOWN_PAYLOAD 16", frameOf(LIGHT_9ABC)), sink.events);
    }

    @Test
    void frameWithBadChecksumIsSkippedAndTheNextFrameDecoded() throws Exception {
        byte[] bad = TEMPERATURE_5678.clone();
        bad[10] ^= 0x40;
        feed(concat(bad, TEMPERATURE_5678));
        assertEquals(List.of("BAD_CHECKSUM 16", frameOf(TEMPERATURE_5678)), sink.events);
    }

    @Test
    void frameWhoseTypeDiffersFromItsPayloadIsSkipped() throws Exception {
        byte[] wrongType = SunSpotCodec.encode(new SunSpotFrame(SPOT_1234, 3, hex("02 01 00 01")));
        feed(concat(wrongType, MOVEMENT_1234));
        assertEquals(List.of("TYPE_MISMATCH 16", frameOf(MOVEMENT_1234)), sink.events);
    }

    @Test
    void frameWithALostByteIsSkippedAndTheNextFrameDecoded() throws Exception {
        byte[] lost = Arrays.copyOf(MOVEMENT_1234, MOVEMENT_1234.length - 1);
        feed(concat(lost, LIGHT_9ABC));
        assertEquals(List.of("BAD_CHECKSUM 15", frameOf(LIGHT_9ABC)), sink.events);
    }

    @Test
    void sameResultWhenSplitAtEveryPairOfByteBoundaries() throws Exception {
        byte[] bad = LIGHT_9ABC.clone();
        bad[10] = 0;
        byte[] stream = concat(hex("01 02 03"), MOVEMENT_1234, hex("FF"), TEMPERATURE_5678, bad, LIGHT_9ABC,
                MOVEMENT_V2_1234);
        feed(stream);
        List<String> expected = List.copyOf(sink.events);
        assertEquals(4, sink.frames);
        assertEquals("LENGTH_MISMATCH 3", expected.get(0));
        assertEquals("BAD_CHECKSUM 16", expected.get(4));
        assertEquals(frameOf(MOVEMENT_V2_1234), expected.get(expected.size() - 1));
        FrameChecks.assertSplitsAlike(stream, expected, () -> {
            RecordingSink r = new RecordingSink();
            return new FrameChecks.Feeding(new SunSpotStreamDecoder(r)::accept, () -> r.events);
        });
    }

    @Test
    void decodesMoreFramesInOneCallThanTheBufferHolds() throws Exception {
        int count = 2000;
        byte[][] frames = new byte[count][];
        for (int i = 0; i < count; i++) {
            frames[i] = SunSpotCodec.encode(SunSpotFrame.of(new SunSpotAddress(i),
                    SunSpotPayloads.encode(new LightStatus(i % 101))));
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
                SunSpotCodec.MAX_FRAME, SunSpotStreamDecoder.BUFFER_SIZE);

        byte[] padding = new byte[SunSpotCodec.MAX_FRAME];
        feed(concat(MOVEMENT_1234, padding, LIGHT_9ABC));
        assertTrue(sink.frames >= 1 && sink.frames <= 2, "frames after garbage: " + sink.frames);
        assertEquals(frameOf(LIGHT_9ABC), sink.events.get(sink.events.size() - 1));
        assertNull(sink.badRun);
    }

    @Test
    void longRunsAreReportedInChunksOfTheBufferSize() throws Exception {
        feed(new byte[10_000]); // zeros: S = L = 0, sensor type 0 is unknown
        assertEquals(List.of("UNKNOWN_PAYLOAD 4096", "UNKNOWN_PAYLOAD 4096"), sink.events);
        assertEquals(SunSpotCodec.HEADER_LENGTH - 1, decoder.buffered());
        feed(MOVEMENT_1234);
        assertEquals(List.of("UNKNOWN_PAYLOAD 4096", "UNKNOWN_PAYLOAD 4096", "UNKNOWN_PAYLOAD 1808",
                frameOf(MOVEMENT_1234)), sink.events);
    }

    @Test
    void resetReportsAnIncompleteFrameAndStartsAfresh() throws Exception {
        feed(Arrays.copyOf(MOVEMENT_V2_1234, 14));
        assertEquals(14, decoder.buffered());
        decoder.reset();
        assertEquals(List.of("TRUNCATED 14"), sink.events);
        assertEquals(0, decoder.buffered());
        feed(MOVEMENT_1234);
        assertEquals(List.of("TRUNCATED 14", frameOf(MOVEMENT_1234)), sink.events);
    }

    @Test
    void resetReportsPendingGarbageAndIncompleteFrameAsOneRun() {
        feed(concat(hex("07 00 00 00 00 00 00 00 00 00 00 00"), Arrays.copyOf(MOVEMENT_1234, 5)));
        assertEquals(SunSpotCodec.HEADER_LENGTH - 1, decoder.buffered(), "6 bytes dropped, 11 wait");
        assertEquals(List.of(), sink.events, "a run is reported when it ends");
        decoder.reset();
        assertEquals(List.of("LENGTH_MISMATCH 17"), sink.events);
        decoder.reset();
        assertEquals(1, sink.events.size(), "nothing left to report");
    }

    @Test
    void rejectsRangesOutsideTheInput() {
        assertThrows(IndexOutOfBoundsException.class, () -> decoder.accept(new byte[4], 2, 3));
        assertThrows(NullPointerException.class, () -> new SunSpotStreamDecoder(null));
    }

    @Test
    void resetNeverReportsARunLongerThanTheBuffer() {
        // 4095 bytes dropped (one short of a reported chunk), then 15 bytes of a 16-byte candidate frame
        byte[] zeros = new byte[SunSpotStreamDecoder.BUFFER_SIZE - 1];
        zeros[0] = 1; // S=1 but L=0: every zero-led candidate after it is dropped too
        feed(concat(zeros, java.util.Arrays.copyOf(LIGHT_9ABC, LIGHT_9ABC.length - 1)));
        assertEquals(List.of(), sink.events);
        decoder.reset();
        assertEquals(2, sink.events.size(), sink.events.toString());
        assertEquals("LENGTH_MISMATCH " + SunSpotStreamDecoder.BUFFER_SIZE, sink.events.get(0));
        assertEquals("TRUNCATED " + (LIGHT_9ABC.length - 2), sink.events.get(1));
        assertEquals(0, decoder.buffered());
    }
}
