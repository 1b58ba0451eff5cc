package org.tinysep.device.support.intake;

import java.util.Optional;
import java.util.function.Function;

/**
 * A node frame in words, the way both protocol families tell their packets ({@code PacketDescriber}s of the AmICA
 * and Sun SPOT bus radios): bytes that are no frame say nothing; a frame says its head (who sent it) and its payload
 * in words, or that the payload was not understood and why. A decoder's bug (a runtime exception) is not taken for
 * a rejection: it is thrown on.
 */
public final class FrameWords {

    /** One decoding step of a family: its codec or its payload table; rejects its input with {@code E}. */
    @FunctionalInterface
    public interface Decoding<T, R, E extends Exception> {
        R decode(T input) throws E;
    }

    private FrameWords() {
    }

    /**
     * @param frame   decodes the frame, e.g. {@code b -> AmicaCodec.decode(b, 0, b.length)} (a lambda: a method
     *                reference could name a type of the protocol's private library)
     * @param head    the frame's head, e.g. {@code "AmICA 1.20 → 0.0 #3: "}
     * @param payload decodes the frame's payload
     * @param words   the payload in words
     * @return the frame in words, or empty when the bytes are no frame of the family
     */
    public static <F, P, E extends Exception> Optional<String> of(byte[] bytes, Decoding<byte[], F, E> frame,
            Function<F, String> head, Decoding<F, P, E> payload, Function<P, String> words) {
        F f;
        try {
            f = frame.decode(bytes);
        } catch (RuntimeException bug) {
            throw bug;
        } catch (Exception rejected) { // the family's protocol exception, the only checked one decode throws
            return Optional.empty();
        }
        try {
            return Optional.of(head.apply(f) + words.apply(payload.decode(f)));
        } catch (RuntimeException bug) {
            throw bug;
        } catch (Exception rejected) {
            return Optional.of(head.apply(f) + "payload not understood (" + rejected.getMessage() + ")");
        }
    }
}
