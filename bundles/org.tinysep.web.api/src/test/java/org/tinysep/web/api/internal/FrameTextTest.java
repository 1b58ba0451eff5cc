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
import org.tinysep.sunspot.protocol.SunSpotCodec;

/** A logged packet in words, through the real codecs: a frame, a frame with a payload not understood, no frame. */
class FrameTextTest {

    @Test
    void aFrameIsToldByItsHeadAndPayload() {
        byte[] heater = AmicaCodec.encode(new AmicaFrame(1, 21, 0, 3, AmicaPayloads.encode(new HeaterControl(40))));
        assertEquals("AmICA 1.21 → 1.0 #3: heater 40 %", AmicaText.of(heater));
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
