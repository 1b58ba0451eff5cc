package org.tinysep.link.frame.testing;

import java.io.ByteArrayOutputStream;

/**
 * Test helpers of both protocol families and the AmICA bus radio base (test jar of org.tinysep.link): byte arrays from
 * hex or decimal text, concatenated, and damaged (a flipped bit, an inserted or a lost byte) for the fuzz tests.
 */
public final class TestBytes {

    private TestBytes() {
    }

    /** @param text space-separated hex bytes, e.g. {@code "04 A1 11"} */
    public static byte[] hex(String text) {
        return parse(text, 16);
    }

    /** @param text space-separated decimal bytes, e.g. {@code "4 161 17"} */
    public static byte[] dec(String text) {
        return parse(text, 10);
    }

    public static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }

    /** @return a copy of {@code f} with bit {@code bit} (0 = lowest bit of the first byte) flipped */
    public static byte[] flip(byte[] f, int bit) {
        byte[] out = f.clone();
        out[bit / 8] ^= (byte) (1 << (bit % 8));
        return out;
    }

    /** @return a copy of {@code f} with {@code b} inserted before index {@code at} */
    public static byte[] insert(byte[] f, int at, byte b) {
        byte[] out = new byte[f.length + 1];
        System.arraycopy(f, 0, out, 0, at);
        out[at] = b;
        System.arraycopy(f, at, out, at + 1, f.length - at);
        return out;
    }

    /** @return a copy of {@code f} without the byte at index {@code at} */
    public static byte[] delete(byte[] f, int at) {
        byte[] out = new byte[f.length - 1];
        System.arraycopy(f, 0, out, 0, at);
        System.arraycopy(f, at + 1, out, at, f.length - at - 1);
        return out;
    }

    private static byte[] parse(String text, int radix) {
        String trimmed = text.trim();
        if (trimmed.isEmpty()) {
            return new byte[0];
        }
        String[] parts = trimmed.split("\\s+");
        byte[] out = new byte[parts.length];
        for (int i = 0; i < parts.length; i++) {
            int v = Integer.parseInt(parts[i], radix);
            if (v < 0 || v > 255) {
                throw new IllegalArgumentException("not a byte: " + parts[i]);
            }
            out[i] = (byte) v;
        }
        return out;
    }
}
