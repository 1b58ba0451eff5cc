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
import org.tinysep.link.frame.testing.StreamDecoderContract;

/** The Sun SPOT rules of the stream decoder; what every family's decoder does is {@link StreamDecoderContract}'s. */
class SunSpotStreamDecoderTest extends StreamDecoderContract<SunSpotFrame, RejectReason, RecordingSink> {

    SunSpotStreamDecoderTest() {
        super(new Family<>(RecordingSink::new, SunSpotStreamDecoder::new, SunSpotCodec::decode,
                List.of(MOVEMENT_1234, LIGHT_9ABC, TEMPERATURE_5678, MOVEMENT_V2_1234),
                i -> SunSpotCodec.encode(SunSpotFrame.of(new SunSpotAddress(i),
                        SunSpotPayloads.encode(new LightStatus(i % 101)))),
                // zeros: S = L = 0 and sensor type 0, unknown; a whole header but one byte waits
                SunSpotCodec.MAX_FRAME, 10, "UNKNOWN_PAYLOAD", SunSpotCodec.HEADER_LENGTH - 1, hex("01 02 03"),
                // "FF" as S differs from L; the next starts see L = 0x12, 0x34, 0x02 ... none equals its S
                "LENGTH_MISMATCH", new Resets(hex("07 00 00 00 00 00 00 00 00 00 00 00"), "LENGTH_MISMATCH",
                        SunSpotCodec.HEADER_LENGTH - 1, longRun(), "LENGTH_MISMATCH",
                        Arrays.copyOf(LIGHT_9ABC, LIGHT_9ABC.length - 1))));
    }

    @Test
    void candidateWithAnUnknownSensorTypeIsDropped() throws Exception {
        byte[] type9 = SunSpotCodec.encode(SunSpotFrame.of(SPOT_1234, hex("09 01 00 01")));
        feed(concat(type9, LIGHT_9ABC));
        assertEquals(List.of("UNKNOWN_PAYLOAD 16", text(LIGHT_9ABC)), sink.events);
    }

    @Test
    void frameWhoseTypeDiffersFromItsPayloadIsSkipped() throws Exception {
        byte[] wrongType = SunSpotCodec.encode(new SunSpotFrame(SPOT_1234, 3, hex("02 01 00 01")));
        feed(concat(wrongType, MOVEMENT_1234));
        assertEquals(List.of("TYPE_MISMATCH 16", text(MOVEMENT_1234)), sink.events);
    }

    /** 4095 bytes: S = 1 but L = 0, so every zero-led candidate after it is dropped too. */
    private static byte[] longRun() {
        byte[] zeros = new byte[SunSpotStreamDecoder.BUFFER_SIZE - 1];
        zeros[0] = 1;
        return zeros;
    }
}
