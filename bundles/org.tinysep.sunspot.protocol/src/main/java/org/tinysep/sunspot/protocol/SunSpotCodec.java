package org.tinysep.sunspot.protocol;

import java.util.Arrays;
import java.util.Objects;

/**
 * Encodes and decodes one Sun SPOT frame (thesis Figure 3.15): size identifier S, the eleven header bytes (source
 * address, sensor type, checksum, payload length L) and S payload bytes. See {@code docs/protocols/sunspot.md} for
 * the byte layout and the checksum.
 * <p>
 * Stateless and thread-safe. For byte streams (serial links) use {@link SunSpotStreamDecoder}.
 */
public final class SunSpotCodec {

    /** Bytes before the payload: size identifier plus the eleven header bytes. */
    public static final int HEADER_LENGTH = 12;
    /** Largest payload, in bytes. */
    public static final int MAX_PAYLOAD = 255;
    /** Largest frame, in bytes: {@link #HEADER_LENGTH} + {@link #MAX_PAYLOAD}. */
    public static final int MAX_FRAME = HEADER_LENGTH + MAX_PAYLOAD;

    static final int SIZE = 0;
    static final int SOURCE = 1;
    static final int ADDRESS_LENGTH = 8;
    static final int SENSOR_TYPE = 9;
    static final int CHECKSUM = 10;
    static final int LENGTH = 11;

    /** CRC-8/SMBUS lookup table: polynomial 0x07, MSB first. */
    private static final byte[] CRC_TABLE = new byte[256];

    static {
        for (int i = 0; i < 256; i++) {
            int crc = i;
            for (int bit = 0; bit < 8; bit++) {
                crc = (crc & 0x80) != 0 ? (crc << 1) ^ 0x07 : crc << 1;
            }
            CRC_TABLE[i] = (byte) crc;
        }
    }

    private SunSpotCodec() {
    }

    /**
     * @param frame the frame
     * @return the frame's bytes, {@link #HEADER_LENGTH} + payload length long, checksum filled in
     */
    public static byte[] encode(SunSpotFrame frame) {
        byte[] payload = frame.payloadUnsafe();
        byte[] out = new byte[HEADER_LENGTH + payload.length];
        out[SIZE] = (byte) payload.length;
        long address = frame.source().value();
        for (int i = 0; i < ADDRESS_LENGTH; i++) {
            out[SOURCE + i] = (byte) (address >>> (8 * (ADDRESS_LENGTH - 1 - i)));
        }
        out[SENSOR_TYPE] = (byte) frame.sensorType();
        out[LENGTH] = (byte) payload.length;
        System.arraycopy(payload, 0, out, HEADER_LENGTH, payload.length);
        out[CHECKSUM] = (byte) checksum(out, 0, payload.length);
        return out;
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
        Objects.checkFromIndexSize(offset, length, buf.length);
        RejectReason reason = check(buf, offset, length);
        if (reason != null) {
            throw new SunSpotProtocolException(reason, detail(reason, buf, offset, length));
        }
        return frameAt(buf, offset);
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
        Objects.checkFromIndexSize(off, len, b.length);
        return crc8(0, b, off, len);
    }

    static int crc8(int crc, byte[] b, int off, int len) {
        for (int i = off; i < off + len; i++) {
            crc = CRC_TABLE[(crc ^ b[i]) & 0xFF] & 0xFF;
        }
        return crc;
    }

    /** The checksum of the frame at {@code off} with the given payload length: CRC over all bytes but CK. */
    static int checksum(byte[] buf, int off, int payloadLength) {
        int crc = crc8(0, buf, off, CHECKSUM);
        return crc8(crc, buf, off + LENGTH, 1 + payloadLength);
    }

    /** @return why the range is not exactly one valid frame, or null if it is */
    static RejectReason check(byte[] buf, int off, int len) {
        if (len < HEADER_LENGTH) {
            return RejectReason.TRUNCATED;
        }
        if (len > MAX_FRAME) {
            return RejectReason.OVERSIZE;
        }
        int size = buf[off + SIZE] & 0xFF;
        if (size != (buf[off + LENGTH] & 0xFF)) {
            return RejectReason.LENGTH_MISMATCH;
        }
        if (len < HEADER_LENGTH + size) {
            return RejectReason.TRUNCATED;
        }
        if (len > HEADER_LENGTH + size) {
            return RejectReason.OVERSIZE;
        }
        if (checksum(buf, off, size) != (buf[off + CHECKSUM] & 0xFF)) {
            return RejectReason.BAD_CHECKSUM;
        }
        if (size == 0 || buf[off + HEADER_LENGTH] != buf[off + SENSOR_TYPE]) {
            return RejectReason.TYPE_MISMATCH;
        }
        return null;
    }

    /** Builds the frame at {@code off}; the caller has checked it. */
    static SunSpotFrame frameAt(byte[] buf, int off) {
        int size = buf[off + SIZE] & 0xFF;
        long address = 0;
        for (int i = 0; i < ADDRESS_LENGTH; i++) {
            address = address << 8 | buf[off + SOURCE + i] & 0xFF;
        }
        byte[] payload = Arrays.copyOfRange(buf, off + HEADER_LENGTH, off + HEADER_LENGTH + size);
        return new SunSpotFrame(new SunSpotAddress(address), buf[off + SENSOR_TYPE] & 0xFF, payload);
    }

    private static String detail(RejectReason reason, byte[] buf, int off, int len) {
        int size = len > SIZE ? buf[off + SIZE] & 0xFF : 0;
        return switch (reason) {
            case TRUNCATED -> len < HEADER_LENGTH
                    ? len + " bytes, a frame has at least " + HEADER_LENGTH
                    : len + " bytes, size identifier " + size + " announces " + (HEADER_LENGTH + size);
            case OVERSIZE -> len > MAX_FRAME
                    ? len + " bytes, a frame has at most " + MAX_FRAME
                    : len + " bytes, size identifier " + size + " announces " + (HEADER_LENGTH + size);
            case LENGTH_MISMATCH -> "size identifier " + size + ", payload length " + (buf[off + LENGTH] & 0xFF);
            case BAD_CHECKSUM -> "checksum " + Hex.ofByte(buf[off + CHECKSUM] & 0xFF) + ", computed "
                    + Hex.ofByte(checksum(buf, off, size));
            case TYPE_MISMATCH -> size == 0
                    ? "sensor type " + (buf[off + SENSOR_TYPE] & 0xFF) + ", empty payload"
                    : "sensor type " + (buf[off + SENSOR_TYPE] & 0xFF) + ", payload starts with "
                            + (buf[off + HEADER_LENGTH] & 0xFF);
            default -> "";
        };
    }
}
