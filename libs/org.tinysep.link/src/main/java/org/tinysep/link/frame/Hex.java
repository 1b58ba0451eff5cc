package org.tinysep.link.frame;

/** Formats bytes as upper-case hex for messages and {@code toString()}, and parses hex digits. */
public final class Hex {

    private static final char[] DIGITS = "0123456789ABCDEF".toCharArray();

    private Hex() {
    }

    /** @return e.g. {@code "52 00 0E"}; empty string for no bytes */
    public static String of(byte[] bytes, int off, int len) {
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
    public static String ofByte(int value) {
        return "0x" + DIGITS[(value >>> 4) & 0x0F] + DIGITS[value & 0x0F];
    }

    /** @return the value of one hex digit, or -1 if {@code c} is none */
    public static int digit(char c) {
        if (c >= '0' && c <= '9') {
            return c - '0';
        }
        if (c >= 'A' && c <= 'F') {
            return c - 'A' + 10;
        }
        if (c >= 'a' && c <= 'f') {
            return c - 'a' + 10;
        }
        return -1;
    }

    /** @return {@code digits} upper-case hex digits of the low bits of {@code value}, zero-padded */
    public static String digits(long value, int digits) {
        char[] out = new char[digits];
        for (int i = digits - 1; i >= 0; i--) {
            out[i] = DIGITS[(int) (value & 0x0F)];
            value >>>= 4;
        }
        return new String(out);
    }
}
