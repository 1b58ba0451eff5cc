package org.tinysep.device.support.intake;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Optional;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/** A frame in words: told, payload not understood with the reason, no frame, a decoder's bug thrown on. */
class FrameWordsTest {

    private static Optional<String> words(byte[] bytes) {
        return FrameWords.<byte[], Integer, Exception>of(bytes, b -> {
            if (b.length < 2) {
                throw new Exception("too short");
            }
            return b;
        }, b -> "node " + b[0] + ": ", b -> {
            if (b[1] < 0) {
                throw new Exception("unknown payload " + b[1]);
            }
            return (int) b[1];
        }, p -> "value " + p);
    }

    @Test
    void aFrameIsToldByItsHeadAndPayload() {
        assertEquals(Optional.of("node 7: value 40"), words(new byte[] {7, 40}));
    }

    @Test
    void aPayloadNotUnderstoodIsSaidWithTheReason() {
        assertEquals(Optional.of("node 7: payload not understood (unknown payload -1)"), words(new byte[] {7, -1}));
    }

    @Test
    void bytesThatAreNoFrameSayNothing() {
        assertEquals(Optional.empty(), words(new byte[] {7}));
    }

    @Test
    void aBugInADecoderIsNotTakenForARejection() {
        assertThrows(IllegalStateException.class, () -> FrameWords.<String, String, Exception>of(new byte[0], b -> {
            throw new IllegalStateException("decoder bug");
        }, Function.identity(), f -> f, Function.identity()));
        assertThrows(IllegalStateException.class, () -> FrameWords.<String, String, Exception>of(new byte[0], b -> "f",
                Function.identity(), f -> {
                    throw new IllegalStateException("decoder bug");
                }, Function.identity()));
    }
}
