package org.tinysep.link.frame;

/**
 * What the public codecs of both protocol families ({@code AmicaCodec}, {@code SunSpotCodec}) share, written once:
 * the largest payload and the CRC-8/SMBUS. A family's codec extends this class (static members are inherited, so
 * {@code AmicaCodec.crc8(...)} and {@code SunSpotCodec.MAX_PAYLOAD} keep working for their users) and adds only the
 * encoding and decoding of its frame, which its {@link FrameFormat} does.
 */
public abstract class FrameCodec {

    /** Largest payload, in bytes. */
    public static final int MAX_PAYLOAD = FrameFormat.MAX_PAYLOAD;

    /** Only the families' codecs extend this class; they are never instantiated. */
    protected FrameCodec() {
    }

    /**
     * CRC-8/SMBUS: polynomial 0x07, initial value 0x00, no reflection, no final XOR. The check value of ASCII
     * {@code "123456789"} is 0xF4.
     *
     * @param b   the bytes
     * @param off the first byte
     * @param len the number of bytes
     * @return the CRC, 0..255
     * @throws IndexOutOfBoundsException if the range lies outside {@code b}
     */
    public static int crc8(byte[] b, int off, int len) {
        return Crc8.of(b, off, len);
    }
}
