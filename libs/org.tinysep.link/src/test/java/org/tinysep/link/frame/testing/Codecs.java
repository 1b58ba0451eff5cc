package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Arrays;
import java.util.function.Function;

/**
 * A protocol family's public codecs as the shared test runners see them, given as method references: the frame
 * codec, the payload codec and the reason of the family's protocol exception.
 *
 * @param decode        the codec's {@code decode(bytes, offset, length)}
 * @param encode        the codec's {@code encode(frame)}
 * @param decodePayload the payload codec's {@code decode(payload)}
 * @param encodePayload the payload codec's {@code encode(payload)}
 * @param headerLength  bytes before the payload
 * @param exception     the family's protocol exception; any other exception fails the test
 * @param reasonOf      the exception's {@code reason()}
 * @param <F>           the frame
 * @param <P>           the payload
 * @param <X>           the family's protocol exception
 */
public record Codecs<F, P, X extends Exception>(FrameDecoder<F> decode, Function<F, byte[]> encode,
        PayloadDecoder<P> decodePayload, Function<P, byte[]> encodePayload, int headerLength, Class<X> exception,
        Function<X, Enum<?>> reasonOf) {

    /** A family's {@code decode(bytes, offset, length)}. */
    @FunctionalInterface
    public interface FrameDecoder<F> {
        F decode(byte[] b, int off, int len) throws Exception;
    }

    /** A family's {@code decode(payload)}. */
    @FunctionalInterface
    public interface PayloadDecoder<P> {
        P decode(byte[] payload) throws Exception;
    }

    /** @return the frame the whole of {@code bytes} is */
    public F frame(byte[] bytes) throws Exception {
        return decode.decode(bytes, 0, bytes.length);
    }

    /** @return the payload of the frame {@code bytes} (what follows the header; empty if it is shorter) */
    public byte[] payloadOf(byte[] bytes) {
        return Arrays.copyOfRange(bytes, Math.min(headerLength, bytes.length), bytes.length);
    }

    /** @return the reason the codec rejects {@code bytes} with; fails if it decodes them */
    public Enum<?> frameRejection(String name, byte[] bytes) {
        return reasonOf.apply(assertThrows(exception, () -> frame(bytes), name));
    }

    /** @return the reason the payload codec rejects {@code payload} with; fails if it decodes it */
    public Enum<?> payloadRejection(String name, byte[] payload) {
        return reasonOf.apply(assertThrows(exception, () -> decodePayload.decode(payload), name));
    }
}
