package org.tinysep.link.frame.testing;

import java.io.ByteArrayOutputStream;

/** Test helpers of both protocol families (test jar of org.tinysep.link): byte arrays from hex or decimal text. */
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
