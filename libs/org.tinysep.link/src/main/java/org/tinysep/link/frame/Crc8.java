package org.tinysep.link.frame;

import java.util.Objects;

/**
 * CRC-8/SMBUS: polynomial 0x07, initial value 0x00, no reflection, no final XOR. The check value of ASCII
 * {@code "123456789"} is 0xF4. Stateless and thread-safe.
 */
public final class Crc8 {

    /** Lookup table, MSB first. */
    private static final byte[] TABLE = new byte[256];

    static {
        for (int i = 0; i < 256; i++) {
            int crc = i;
            for (int bit = 0; bit < 8; bit++) {
                crc = (crc & 0x80) != 0 ? (crc << 1) ^ 0x07 : crc << 1;
            }
            TABLE[i] = (byte) crc;
        }
    }

    private Crc8() {
    }

    /**
     * @param b   the bytes
     * @param off the first byte
     * @param len the number of bytes
     * @return the CRC, 0..255
     * @throws IndexOutOfBoundsException if the range lies outside {@code b}
     */
    public static int of(byte[] b, int off, int len) {
        Objects.checkFromIndexSize(off, len, b.length);
        return update(0, b, off, len);
    }

    /** Continues {@code crc} over the range; the caller has checked it. */
    public static int update(int crc, byte[] b, int off, int len) {
        for (int i = off; i < off + len; i++) {
            crc = TABLE[(crc ^ b[i]) & 0xFF] & 0xFF;
        }
        return crc;
    }
}
