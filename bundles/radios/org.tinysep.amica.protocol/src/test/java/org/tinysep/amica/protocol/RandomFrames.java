package org.tinysep.amica.protocol;

import java.util.Arrays;
import java.util.Random;
import org.tinysep.link.frame.testing.TestBytes;

/**
 * Random input for the fuzz tests, drawn from a {@link Random} (see {@link Fuzz}): valid frames (Table 3.1
 * payloads and arbitrary ones), garbage, and frames damaged the way a radio or a serial line damages them (bit
 * flips, truncations, insertions, lost bytes, garbage around them).
 */
final class RandomFrames {

    private RandomFrames() {
    }

    /** A payload of thesis Table 3.1 with any valid values. */
    static byte[] tablePayload(Random r) {
        AmicaPayload payload = switch (r.nextInt(6)) {
            case 0 -> new KeepAlive(u32(r), Fuzz.between(r, 0, 0xFFFF), Fuzz.between(r, 0, 0xFFFF),
                    Fuzz.between(r, 0, 0xFFFF), u32(r));
            case 1 -> new MotionDetection(r.nextBoolean());
            case 2 -> new ReedSwitchStatus(r.nextBoolean());
            case 3 -> new LightControl(Fuzz.between(r, 0, 100));
            case 4 -> new SpeakerControl(Fuzz.between(r, 0, 100));
            default -> new HeaterControl(Fuzz.between(r, 0, 100));
        };
        return AmicaPayloads.encode(payload);
    }

    private static long u32(Random r) {
        return switch (r.nextInt(16)) {
            case 0 -> 0;
            case 1 -> 0xFFFF_FFFFL;
            default -> r.nextLong() & 0xFFFF_FFFFL;
        };
    }

    /** Table 3.1 payloads four times in five, otherwise any bytes (0..255 of them, so frames up to the maximum). */
    static byte[] payload(Random r) {
        return Fuzz.weighted(r, 4, 1) == 0 ? tablePayload(r) : Fuzz.bytes(r, AmicaCodec.MAX_PAYLOAD);
    }

    /** A frame with any addresses, sequence number and {@link #payload}. */
    static AmicaFrame frame(Random r) {
        return frame(r, payload(r));
    }

    static AmicaFrame frame(Random r, byte[] payload) {
        return new AmicaFrame(octet(r), octet(r), octet(r), octet(r), payload);
    }

    private static int octet(Random r) {
        return Fuzz.between(r, 0, 255);
    }

    /** An encoded valid frame. */
    static byte[] validFrame(Random r) {
        return AmicaCodec.encode(frame(r));
    }

    /** An encoded valid frame whose first byte is not 0xA1 (payloads of Table 3.1 only). */
    static byte[] tableFrame(Random r) {
        return AmicaCodec.encode(frame(r, tablePayload(r)));
    }

    /** 0..maxSize random bytes. */
    static byte[] garbage(Random r, int maxSize) {
        return Fuzz.bytes(r, maxSize);
    }

    /** A valid frame damaged once: a bit flip, a truncation, an inserted or lost byte, garbage before or after. */
    static byte[] damagedFrame(Random r) {
        byte[] f = validFrame(r);
        return switch (r.nextInt(6)) {
            case 0 -> flip(f, r.nextInt(f.length * 8));
            case 1 -> Arrays.copyOf(f, Fuzz.between(r, 0, f.length - 1));
            case 2 -> insert(f, Fuzz.between(r, 0, f.length), Fuzz.anyByte(r));
            case 3 -> delete(f, Fuzz.between(r, 0, f.length - 1));
            case 4 -> concat(garbage(r, 64), f);
            default -> concat(f, garbage(r, 64));
        };
    }

    /** Any of: garbage of up to 300 bytes, a valid frame, a damaged frame (as likely each). */
    static byte[] anyInput(Random r) {
        return switch (r.nextInt(3)) {
            case 0 -> garbage(r, 300);
            case 1 -> validFrame(r);
            default -> damagedFrame(r);
        };
    }

    /** A byte stream as a serial line delivers it: 0..maxParts frames, damaged frames and garbage, in any order. */
    static byte[] stream(Random r, int maxParts) {
        byte[][] parts = new byte[Fuzz.between(r, 0, maxParts)][];
        for (int i = 0; i < parts.length; i++) {
            parts[i] = switch (Fuzz.weighted(r, 5, 3, 2)) {
                case 0 -> validFrame(r);
                case 1 -> damagedFrame(r);
                default -> garbage(r, 300);
            };
        }
        return concat(parts);
    }

    static byte[] flip(byte[] f, int bit) {
        return TestBytes.flip(f, bit);
    }

    static byte[] insert(byte[] f, int at, byte b) {
        return TestBytes.insert(f, at, b);
    }

    static byte[] delete(byte[] f, int at) {
        return TestBytes.delete(f, at);
    }

    static byte[] concat(byte[]... parts) {
        return TestBytes.concat(parts);
    }
}
