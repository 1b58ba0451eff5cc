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
import org.tinysep.link.frame.testing.StreamDecoderContract;

/** The AmICA rules of the stream decoder; what every family's decoder does is {@link StreamDecoderContract}'s. */
class AmicaStreamDecoderTest extends StreamDecoderContract<AmicaFrame, RejectReason, RecordingSink> {

    AmicaStreamDecoderTest() {
        super(new Family<>(RecordingSink::new, AmicaStreamDecoder::new, AmicaCodec::decode,
                List.of(MOVEMENT_1_17, REED_OPEN_1_18, LIGHT_40_TO_1_20, KEEP_ALIVE_1_17),
                i -> AmicaCodec.encode(new AmicaFrame(1, 17, 0, i % 256, new byte[] {5, 2, 0, (byte) (i % 101)})),
                AmicaCodec.MAX_FRAME, 6, "BAD_HEADER", 1,
                hex("01 A1 02"), // garbage that looks like a header with S = L = 1: the CRC rejects it
                "BAD_HEADER", new Resets(hex("00 00 00"), "BAD_HEADER", 5, new byte[AmicaStreamDecoder.BUFFER_SIZE - 1],
                        "BAD_HEADER", Arrays.copyOf(KEEP_ALIVE_1_17, 10))));
    }

    @Test
    void skipsGarbageBetweenFrames() throws Exception {
        feed(concat(MOVEMENT_1_17, hex("AA BB"), REED_OPEN_1_18));
        assertEquals(List.of(text(MOVEMENT_1_17), "BAD_HEADER 2", text(REED_OPEN_1_18)), sink.events);
    }

    @Test
    void sizeDifferentFromLengthIsSkipped() throws Exception {
        byte[] mismatch = MOVEMENT_1_17.clone();
        mismatch[7] = 9;
        feed(concat(mismatch, MOVEMENT_1_17));
        assertEquals(List.of("LENGTH_MISMATCH 12", text(MOVEMENT_1_17)), sink.events);
    }

    @Test
    void decodesEmptyPayloadFrames() throws Exception {
        byte[] empty = hex("00 A1 11 00 01 0A 47 00");
        feed(concat(empty, empty));
        assertEquals(List.of(text(empty), text(empty)), sink.events);
    }
}
