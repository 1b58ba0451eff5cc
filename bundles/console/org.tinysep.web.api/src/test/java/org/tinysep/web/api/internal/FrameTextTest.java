package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** A logged packet in words, through the real codecs: a frame, a frame with a payload not understood, no frame. */
class FrameTextTest {

    @Test
    void aFrameIsToldByItsHeadAndPayload() {
        byte[] heater = AmicaCodec.encode(new AmicaFrame(1, 21, 0, 3, AmicaPayloads.encode(new HeaterControl(40))));
        assertEquals("AmICA 1.21 → 1.0 #3: heater 40 %", AmicaText.of(heater));
    }

    @Test
    void personNodeReportsAreToldInWords() {
        SunSpotAddress anna = SunSpotAddress.parse("0014.4F01.0000.A001");
        assertEquals("Sun SPOT 0014.4F01.0000.A001: switch 1 pressed", SunSpotText.of(SunSpotCodec.encode(
                SunSpotFrame.of(anna, SunSpotPayloads.encode(new ButtonReport(1, true))))));
        assertEquals("Sun SPOT 0014.4F01.0000.A001: movement summary over 2000 ms: mean (12, -985, 110) mg, spread "
                + "6 mg, peak 1003 mg", SunSpotText.of(SunSpotCodec.encode(SunSpotFrame.of(anna, SunSpotPayloads.encode(
                new MovementSummaryReport(2000, new AccelerationSample(12, -985, 110), 6, 1003))))));
        BurstChunk last = BurstChunk.split(7, 50, 50, java.util.Collections.nCopies(150,
                new AccelerationSample(0, -1000, 0))).get(4);
        assertEquals("Sun SPOT 0014.4F01.0000.A001: acceleration burst 7, chunk 5 of 5: 22 samples at 50 Hz",
                SunSpotText.of(SunSpotCodec.encode(SunSpotFrame.of(anna, SunSpotPayloads.encode(last)))));
    }

    @Test
    void aPayloadNotUnderstoodIsSaidWithTheReason() {
        byte[] unknown = AmicaCodec.encode(new AmicaFrame(1, 21, 0, 3, new byte[] {9, 9, 9, 9}));
        String text = AmicaText.of(unknown);
        assertTrue(text.startsWith("AmICA 1.21 → 1.0 #3: payload not understood (UNKNOWN_PAYLOAD"), text);
    }

    @Test
    void bytesThatAreNoFrameOfTheFamilySayNothing() {
        assertEquals("", AmicaText.of(new byte[] {1, 2, 3}));
        assertEquals("", SunSpotText.of(new byte[] {1, 2, 3}));
        assertEquals("", SunSpotText.of(new byte[SunSpotCodec.MAX_FRAME + 1]));
    }

    @Test
    void aBugInADecoderIsNotTakenForARejection() {
        assertThrows(IllegalStateException.class, () -> FrameText.<String, String, Exception>of(new byte[0], b -> {
            throw new IllegalStateException("decoder bug");
        }, Function.identity(), f -> f, Function.identity()));
        assertThrows(IllegalStateException.class, () -> FrameText.<String, String, Exception>of(new byte[0], b -> "f",
                Function.identity(), f -> {
                    throw new IllegalStateException("decoder bug");
                }, Function.identity()));
    }
}
