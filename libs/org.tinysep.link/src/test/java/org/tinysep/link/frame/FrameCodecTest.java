package org.tinysep.link.frame;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.FrameChecks;

/**
 * The CRC both families' codecs inherit ({@code AmicaCodec.crc8}, {@code SunSpotCodec.crc8} are this method; their
 * tests use it through those names). Moved here from both codec tests, where it was tested twice.
 */
class FrameCodecTest {

    @Test
    void crc8CheckValueIsF4() {
        FrameChecks.assertCheckValue(FrameCodec::crc8);
    }

    @Test
    void crc8TableMatchesBitwiseDefinition() {
        FrameChecks.assertMatchesBitwiseDefinition(FrameCodec::crc8);
    }

    @Test
    void largestPayloadIsTheFormatsLimit() {
        assertEquals(255, FrameCodec.MAX_PAYLOAD);
        assertEquals(FrameFormat.MAX_PAYLOAD, FrameCodec.MAX_PAYLOAD);
    }
}
