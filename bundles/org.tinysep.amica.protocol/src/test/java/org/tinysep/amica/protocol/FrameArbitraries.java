package org.tinysep.amica.protocol;

import java.util.Arrays;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Tuple;
import net.jqwik.api.Tuple.Tuple2;

/**
 * jqwik generators for property tests: valid frames (Table 3.1 payloads and arbitrary ones), garbage, and frames
 * damaged the way a radio or a serial line damages them (bit flips, truncations, insertions, lost bytes,
 * garbage around them).
 */
final class FrameArbitraries {

    private FrameArbitraries() {
    }

    /** Payloads of thesis Table 3.1 with any valid values. */
    static Arbitrary<byte[]> tablePayloads() {
        Arbitrary<Integer> u16 = Arbitraries.integers().between(0, 0xFFFF);
        Arbitrary<Long> u32 = Arbitraries.longs().between(0, 0xFFFF_FFFFL);
        Arbitrary<AmicaPayload> keepAlive = Combinators.combine(u32, u16, u16, u16, u32).as(KeepAlive::new);
        Arbitrary<Integer> percent = Arbitraries.integers().between(0, 100);
        Arbitrary<AmicaPayload> payload = Arbitraries.oneOf(keepAlive,
                Arbitraries.of(true, false).map(MotionDetection::new),
                Arbitraries.of(true, false).map(ReedSwitchStatus::new),
                percent.map(LightControl::new), percent.map(SpeakerControl::new), percent.map(HeaterControl::new));
        return payload.map(AmicaPayloads::encode);
    }

    /** Table 3.1 payloads mostly, now and then any bytes (0..255 of them, so frames up to the maximum). */
    static Arbitrary<byte[]> payloads() {
        return Arbitraries.frequencyOf(List.of(
                weighted(4, tablePayloads()),
                weighted(1, Arbitraries.bytes().array(byte[].class).ofMaxSize(AmicaCodec.MAX_PAYLOAD))));
    }

    static Arbitrary<AmicaFrame> frames(Arbitrary<byte[]> payloads) {
        Arbitrary<Integer> octet = Arbitraries.integers().between(0, 255);
        return Combinators.combine(octet, octet, octet, octet, payloads).as(AmicaFrame::new);
    }

    /** Encoded valid frames. */
    static Arbitrary<byte[]> validFrames() {
        return frames(payloads()).map(AmicaCodec::encode);
    }

    /** Encoded valid frames whose first byte is not 0xA1 (payloads of Table 3.1 only). */
    static Arbitrary<byte[]> tableFrames() {
        return frames(tablePayloads()).map(AmicaCodec::encode);
    }

    static Arbitrary<byte[]> garbage(int maxSize) {
        return Arbitraries.bytes().array(byte[].class).ofMaxSize(maxSize);
    }

    /** Valid frames damaged once: a bit flip, a truncation, an inserted or lost byte, garbage before or after. */
    static Arbitrary<byte[]> damagedFrames() {
        return validFrames().flatMap(f -> Arbitraries.oneOf(
                Arbitraries.integers().between(0, f.length * 8 - 1).map(bit -> flip(f, bit)),
                Arbitraries.integers().between(0, f.length - 1).map(n -> Arrays.copyOf(f, n)),
                Combinators.combine(Arbitraries.integers().between(0, f.length), Arbitraries.bytes())
                        .as((at, b) -> insert(f, at, b)),
                Arbitraries.integers().between(0, f.length - 1).map(at -> delete(f, at)),
                garbage(64).map(g -> concat(g, f)),
                garbage(64).map(g -> concat(f, g))));
    }

    /** A byte stream as a serial line delivers it: frames, damaged frames and garbage, in any order. */
    static Arbitrary<byte[]> streams(int maxParts) {
        return Arbitraries.frequencyOf(List.of(weighted(5, validFrames()), weighted(3, damagedFrames()),
                        weighted(2, garbage(300))))
                .list().ofMaxSize(maxParts).map(parts -> concat(parts.toArray(byte[][]::new)));
    }

    static Tuple2<Integer, Arbitrary<byte[]>> weighted(int weight, Arbitrary<byte[]> a) {
        return Tuple.of(weight, a);
    }

    static byte[] flip(byte[] f, int bit) {
        byte[] out = f.clone();
        out[bit / 8] ^= (byte) (1 << (bit % 8));
        return out;
    }

    static byte[] insert(byte[] f, int at, byte b) {
        byte[] out = new byte[f.length + 1];
        System.arraycopy(f, 0, out, 0, at);
        out[at] = b;
        System.arraycopy(f, at, out, at + 1, f.length - at);
        return out;
    }

    static byte[] delete(byte[] f, int at) {
        byte[] out = new byte[f.length - 1];
        System.arraycopy(f, 0, out, 0, at);
        System.arraycopy(f, at + 1, out, at, f.length - at - 1);
        return out;
    }

    static byte[] concat(byte[]... parts) {
        return TestBytes.concat(parts);
    }
}
