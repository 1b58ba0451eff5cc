package org.tinysep.amica.protocol;

/** Formats bytes as upper-case hex for messages and {@code toString()}; package-private helper. */
final class Hex {

    private static final char[] DIGITS = "0123456789ABCDEF".toCharArray();

    private Hex() {
    }

    /** @return e.g. {@code "52 00 0E"}; empty string for no bytes */
    static String of(byte[] bytes, int off, int len) {
        StringBuilder sb = new StringBuilder(len * 3);
        for (int i = 0; i < len; i++) {
            if (i > 0) {
                sb.append(' ');
            }
            int b = bytes[off + i] & 0xFF;
            sb.append(DIGITS[b >>> 4]).append(DIGITS[b & 0x0F]);
        }
        return sb.toString();
    }

    /** @return e.g. {@code "0xA1"} */
    static String ofByte(int value) {
        return "0x" + DIGITS[(value >>> 4) & 0x0F] + DIGITS[value & 0x0F];
    }
}
