package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.Crc8;
import org.tinysep.link.frame.FrameFormat;

/**
 * Encodes and decodes one Sun SPOT frame (thesis Figure 3.15): size identifier S, the eleven header bytes (source
 * address, sensor type, checksum, payload length L) and S payload bytes. See {@code docs/protocols/sunspot.md} for
 * the byte layout and the checksum.
 * <p>
 * The layout and the checks are shared with the AmICA protocol ({@code org.tinysep.link.frame.FrameFormat});
 * this family adds its address, its sensor type and the type rule ({@code SunSpotFormat}).
 * <p>
 * Stateless and thread-safe. For byte streams (serial links) use {@link SunSpotStreamDecoder}.
 */
public final class SunSpotCodec {

    /** Bytes before the payload: size identifier plus the eleven header bytes. */
    public static final int HEADER_LENGTH = 12;
    /** Largest payload, in bytes. */
    public static final int MAX_PAYLOAD = FrameFormat.MAX_PAYLOAD;
    /** Largest frame, in bytes: {@link #HEADER_LENGTH} + {@link #MAX_PAYLOAD}. */
    public static final int MAX_FRAME = HEADER_LENGTH + MAX_PAYLOAD;

    static final int SIZE = 0;
    static final int SOURCE = 1;
    static final int ADDRESS_LENGTH = 8;
    static final int SENSOR_TYPE = 9;
    static final int CHECKSUM = 10;
    static final int LENGTH = 11;

    private SunSpotCodec() {
    }

    /**
     * @param frame the frame
     * @return the frame's bytes, {@link #HEADER_LENGTH} + payload length long, checksum filled in
     */
    public static byte[] encode(SunSpotFrame frame) {
        byte[] payload = frame.payloadUnsafe();
        byte[] out = new byte[HEADER_LENGTH + payload.length];
        long address = frame.source().value();
        for (int i = 0; i < ADDRESS_LENGTH; i++) {
            out[SOURCE + i] = (byte) (address >>> (8 * (ADDRESS_LENGTH - 1 - i)));
        }
        out[SENSOR_TYPE] = (byte) frame.sensorType();
        System.arraycopy(payload, 0, out, HEADER_LENGTH, payload.length);
        return SunSpotFormat.INSTANCE.seal(out, payload.length);
    }

    /**
     * Decodes exactly one frame that occupies the whole range, as in a UDP datagram.
     *
     * @param buf    the bytes
     * @param offset where the frame starts
     * @param length the number of bytes; must be exactly the frame's length
     * @return the frame; its sensor type equals its payload's first byte
     * @throws SunSpotProtocolException  with {@link RejectReason#TRUNCATED}, {@link RejectReason#OVERSIZE},
     *                                   {@link RejectReason#LENGTH_MISMATCH}, {@link RejectReason#BAD_CHECKSUM} or
     *                                   {@link RejectReason#TYPE_MISMATCH}
     * @throws IndexOutOfBoundsException if the range lies outside {@code buf}
     */
    public static SunSpotFrame decode(byte[] buf, int offset, int length) throws SunSpotProtocolException {
        return SunSpotFormat.INSTANCE.decode(buf, offset, length, SunSpotProtocolException::new);
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
