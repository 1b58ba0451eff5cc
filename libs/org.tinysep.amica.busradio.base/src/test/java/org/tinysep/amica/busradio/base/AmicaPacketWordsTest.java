package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.MotionDetection;

/** AmICA packets in words, through the real codec: a frame, a payload not understood, no frame. */
class AmicaPacketWordsTest {

    private final AmicaPacketWords words = new AmicaPacketWords();

    @Test
    void aFrameIsToldByItsHeadAndPayload() {
        byte[] heater = AmicaCodec.encode(new AmicaFrame(1, 21, 0, 3, AmicaPayloads.encode(new HeaterControl(40))));
        assertEquals(Optional.of("AmICA 1.21 → 1.0 #3: heater 40 %"), words.describe(heater));
        byte[] motion = AmicaCodec.encode(new AmicaFrame(1, 17, 0, 6, AmicaPayloads.encode(new MotionDetection(true))));
        assertEquals(Optional.of("AmICA 1.17 → 1.0 #6: motion detected"), words.describe(motion));
        assertEquals("AmICA", words.protocol());
    }

    @Test
    void aPayloadNotUnderstoodIsSaidWithTheReason() {
        byte[] unknown = AmicaCodec.encode(new AmicaFrame(1, 21, 0, 3, new byte[] {9, 9, 9, 9}));
        String text = words.describe(unknown).orElseThrow();
        assertTrue(text.startsWith("AmICA 1.21 → 1.0 #3: payload not understood (UNKNOWN_PAYLOAD"), text);
    }

    @Test
    void bytesThatAreNoAmicaFrameSayNothing() {
        assertEquals(Optional.empty(), words.describe(new byte[] {1, 2, 3}));
        assertEquals(Optional.empty(), words.describe(new byte[0]));
    }
}
