package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collections;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** Sun SPOT packets in words, through the real codec, and which origins are this protocol's. */
class SunSpotPacketDescriberTest {

    private final SunSpotPacketDescriber words = new SunSpotPacketDescriber();
    private final SunSpotAddress anna = SunSpotAddress.parse("0014.4F01.0000.A001");

    private byte[] frame(org.tinysep.sunspot.protocol.SunSpotPayload p) {
        return SunSpotCodec.encode(SunSpotFrame.of(anna, SunSpotPayloads.encode(p)));
    }

    @Test
    void personNodeReportsAreToldInWords() {
        assertEquals(Optional.of("Sun SPOT 0014.4F01.0000.A001: switch 1 pressed"),
                words.describe(frame(new ButtonReport(1, true))));
        assertEquals(Optional.of("Sun SPOT 0014.4F01.0000.A001: movement summary over 2000 ms: mean (12, -985, 110) "
                + "mg, spread 6 mg, peak 1003 mg"), words.describe(frame(
                new MovementSummaryReport(2000, new AccelerationSample(12, -985, 110), 6, 1003))));
        BurstChunk last = BurstChunk.split(7, 50, 50, Collections.nCopies(150, new AccelerationSample(0, -1000, 0)))
                .get(4);
        assertEquals(Optional.of("Sun SPOT 0014.4F01.0000.A001: acceleration burst 7, chunk 5 of 5: 22 samples at 50 Hz"),
                words.describe(frame(last)));
    }

    @Test
    void bytesThatAreNoSunSpotFrameSayNothing() {
        assertEquals(Optional.empty(), words.describe(new byte[] {1, 2, 3}));
        assertEquals(Optional.empty(), words.describe(new byte[SunSpotCodec.MAX_FRAME + 1]));
    }

    @Test
    void itsOwnOriginsAreKnown() {
        assertTrue(words.usualFor("node 0014.4F01.0000.A001 via udp 127.0.0.1:5100"));
        assertTrue(words.usualFor("SunSpotBusRadio"));
        assertFalse(words.usualFor("node 1:17 via 127.0.0.1:5000"));
    }
}
