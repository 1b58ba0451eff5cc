package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.Hex;

/**
 * Identity of a Sun SPOT node: its 64-bit IEEE address, unsigned. Written as the Sun SPOT SDK writes it: four
 * dot-separated groups of four upper-case hex digits, most significant first, e.g. {@code 0014.4F01.0000.1234}.
 * In a frame it occupies eight bytes, big-endian.
 *
 * @param value the 64 address bits (the sign of the {@code long} carries no meaning)
 */
public record SunSpotAddress(long value) {

    private static final int GROUPS = 4;
    private static final int GROUP_DIGITS = 4;
    private static final int TEXT_LENGTH = GROUPS * GROUP_DIGITS + GROUPS - 1;

    /**
     * Parses the dotted form written by {@link #toString()}; hex digits may be upper or lower case.
     *
     * @param text e.g. {@code "0014.4F01.0000.1234"}
     * @return the address
     * @throws IllegalArgumentException if the text is null or not four dot-separated groups of four hex digits
     */
    public static SunSpotAddress parse(String text) {
        if (text == null) {
            throw new IllegalArgumentException("Sun SPOT address is null; expected e.g. 0014.4F01.0000.1234");
        }
        if (text.length() != TEXT_LENGTH) {
            throw bad(text, "has " + text.length() + " characters, expected " + TEXT_LENGTH);
        }
        long value = 0;
        for (int i = 0; i < TEXT_LENGTH; i++) {
            char c = text.charAt(i);
            if (i % (GROUP_DIGITS + 1) == GROUP_DIGITS) {
                if (c != '.') {
                    throw bad(text, "character " + (i + 1) + " must be a dot");
                }
                continue;
            }
            int d = Hex.digit(c);
            if (d < 0) {
                throw bad(text, "character " + (i + 1) + " '" + c + "' is not a hex digit");
            }
            value = value << 4 | d;
        }
        return new SunSpotAddress(value);
    }

    /** @return e.g. {@code 0014.4F01.0000.1234} */
    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder(TEXT_LENGTH);
        for (int g = GROUPS - 1; g >= 0; g--) {
            sb.append(Hex.digits(value >>> (g * 16), GROUP_DIGITS));
            if (g > 0) {
                sb.append('.');
            }
        }
        return sb.toString();
    }

    private static IllegalArgumentException bad(String text, String why) {
        return new IllegalArgumentException("Sun SPOT address '" + text + "' " + why
                + "; expected four dot-separated groups of four hex digits, e.g. 0014.4F01.0000.1234");
    }
}
