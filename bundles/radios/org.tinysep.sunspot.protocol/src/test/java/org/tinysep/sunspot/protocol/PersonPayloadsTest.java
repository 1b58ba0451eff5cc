package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The person node's reports (protocol 2.2.0) beyond the document's vectors: bursts, limits, round trips. */
class PersonPayloadsTest {

    private static final SunSpotAddress NODE = SunSpotAddress.parse("0014.4F01.0000.A001");

    private static List<AccelerationSample> samples(int n, long seed) {
        Random r = new Random(seed);
        List<AccelerationSample> s = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            s.add(new AccelerationSample(r.nextInt(32001) - 16000, r.nextInt(32001) - 16000,
                    r.nextInt(32001) - 16000));
        }
        return s;
    }

    @Test
    void theStandardBurstIsFiveChunksOfAtMost200BytesAndComesBackWhole() throws Exception {
        List<AccelerationSample> burst = samples(150, 1);
        List<BurstChunk> chunks = BurstChunk.split(7, 50, 50, burst);

        assertEquals(List.of(32, 32, 32, 32, 22), chunks.stream().map(c -> c.samples().size()).toList());
        List<AccelerationSample> back = new ArrayList<>();
        int frameBytes = 0;
        for (BurstChunk c : chunks) {
            byte[] payload = SunSpotPayloads.encode(c);
            assertTrue(payload.length <= 200, "chunk of " + payload.length + " bytes");
            byte[] frame = SunSpotCodec.encode(SunSpotFrame.of(NODE, payload));
            frameBytes += frame.length;
            BurstChunk decoded = (BurstChunk) SunSpotPayloads.decode(SunSpotCodec.decode(frame, 0, frame.length)
                    .payload());
            assertEquals(c, decoded);
            assertEquals(5, decoded.chunkCount());
            back.addAll(decoded.samples());
        }
        assertEquals(burst, back);
        assertEquals(1000, frameBytes, "the radio budget in docs/protocols/sunspot.md counts 1000 bytes a burst");
        assertTrue(chunks.get(4).last());
    }

    @Test
    void summariesAndButtonsRoundTripAndHaveTheDocumentedSizes() throws Exception {
        MovementSummaryReport s = new MovementSummaryReport(65535, new AccelerationSample(-16000, 16000, -1),
                5000, MovementSummaryReport.MAX_MAGNITUDE_MG);
        byte[] p = SunSpotPayloads.encode(s);
        assertEquals(14, p.length);
        assertEquals(26, SunSpotCodec.encode(SunSpotFrame.of(NODE, p)).length, "26 bytes a summary (budget)");
        assertEquals(s, SunSpotPayloads.decode(p));
        for (int b = 1; b <= 2; b++) {
            for (boolean pressed : new boolean[] {true, false}) {
                byte[] bp = SunSpotPayloads.encode(new ButtonReport(b, pressed));
                assertEquals(16, SunSpotCodec.encode(SunSpotFrame.of(NODE, bp)).length);
                assertEquals(new ButtonReport(b, pressed), SunSpotPayloads.decode(bp));
            }
        }
    }

    @Test
    void recordsRefuseWhatTheDecoderRefuses() {
        AccelerationSample up = new AccelerationSample(0, 0, 1000);
        assertThrows(IllegalArgumentException.class, () -> new AccelerationSample(16001, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new AccelerationSample(0, -16001, 0));
        assertThrows(IllegalArgumentException.class, () -> new ButtonReport(0, true));
        assertThrows(IllegalArgumentException.class, () -> new ButtonReport(3, true));
        assertThrows(IllegalArgumentException.class, () -> new MovementSummaryReport(0, up, 0, 1000));
        assertThrows(IllegalArgumentException.class, () -> new MovementSummaryReport(2000, up, 1001, 1000));
        assertThrows(IllegalArgumentException.class, () -> new MovementSummaryReport(2000, up, 0, 997));
        new MovementSummaryReport(2000, up, 0, 998); // within the 2 mg rounding slack
        assertThrows(IllegalArgumentException.class, () -> BurstChunk.split(0, 50, 0, List.of()));
        assertThrows(IllegalArgumentException.class, () -> BurstChunk.split(0, 50, 0, samples(513, 2)));
        assertThrows(IllegalArgumentException.class, () -> BurstChunk.split(0, 50, 150, samples(150, 3)));
        assertThrows(IllegalArgumentException.class, () -> BurstChunk.split(256, 50, 0, samples(3, 3)));
        assertThrows(IllegalArgumentException.class, () -> BurstChunk.split(0, 256, 0, samples(3, 3)));
        assertEquals(16, BurstChunk.split(255, 255, 511, samples(512, 4)).size());
    }

    @Test
    void everyEncodedChunkDecodesToItself() throws Exception {
        Random r = new Random(26);
        for (int i = 0; i < 300; i++) {
            int n = 1 + r.nextInt(512);
            int before = r.nextInt(n);
            for (BurstChunk c : BurstChunk.split(r.nextInt(256), 1 + r.nextInt(255), before, samples(n, i))) {
                assertEquals(c, SunSpotPayloads.decode(SunSpotPayloads.encode(c)), "case " + i);
            }
        }
    }
}
