package org.tinysep.amica.protocol;

import org.tinysep.link.frame.Crc8;
import org.tinysep.link.frame.FrameFormat;

/**
 * Encodes and decodes one AmICA frame: size identifier S, the seven header bytes (header value, source,
 * destination, netgroup, sequence, checksum, payload length L) and S payload bytes. See
 * {@code docs/protocols/amica.md} for the byte layout and the checksum.
 * <p>
 * The layout and the checks are shared with the Sun SPOT protocol ({@code org.tinysep.link.frame.FrameFormat});
 * this family adds the header value and its header fields ({@code AmicaFormat}).
 * <p>
 * Stateless and thread-safe. For byte streams (serial links) use {@link AmicaStreamDecoder}.
 */
public final class AmicaCodec {

    /** Header value of AmICA node protocol v1; frames with another value are rejected. */
    public static final int HEADER_VALUE = 0xA1;
    /** Bytes before the payload: size identifier plus the seven header bytes. */
    public static final int HEADER_LENGTH = 8;
    /** Largest payload, in bytes. */
    public static final int MAX_PAYLOAD = FrameFormat.MAX_PAYLOAD;
    /** Largest frame, in bytes: {@link #HEADER_LENGTH} + {@link #MAX_PAYLOAD}. */
    public static final int MAX_FRAME = HEADER_LENGTH + MAX_PAYLOAD;
    /** Address of the platform (base station) within every netgroup. */
    public static final int PLATFORM_ADDRESS = 0;

    static final int SIZE = 0;
    static final int HEADER = 1;
    static final int SOURCE = 2;
    static final int DESTINATION = 3;
    static final int NETGROUP = 4;
    static final int SEQUENCE = 5;
    static final int CHECKSUM = 6;
    static final int LENGTH = 7;

    private AmicaCodec() {
    }

    /**
     * @param frame the frame
     * @return the frame's bytes, {@link #HEADER_LENGTH} + payload length long, checksum filled in
     */
    public static byte[] encode(AmicaFrame frame) {
        byte[] payload = frame.payloadUnsafe();
        byte[] out = new byte[HEADER_LENGTH + payload.length];
        out[HEADER] = (byte) HEADER_VALUE;
        out[SOURCE] = (byte) frame.source();
        out[DESTINATION] = (byte) frame.destination();
        out[NETGROUP] = (byte) frame.netgroup();
        out[SEQUENCE] = (byte) frame.sequence();
        System.arraycopy(payload, 0, out, HEADER_LENGTH, payload.length);
        return AmicaFormat.INSTANCE.seal(out, payload.length);
    }

    /**
     * Decodes exactly one frame that occupies the whole range, as in a UDP datagram.
     *
     * @param buf    the bytes
     * @param offset where the frame starts
     * @param length the number of bytes; must be exactly the frame's length
     * @return the frame
     * @throws AmicaProtocolException    with {@link RejectReason#TRUNCATED}, {@link RejectReason#OVERSIZE},
     *                                   {@link RejectReason#BAD_HEADER}, {@link RejectReason#LENGTH_MISMATCH} or
     *                                   {@link RejectReason#BAD_CHECKSUM}
     * @throws IndexOutOfBoundsException if the range lies outside {@code buf}
     */
    public static AmicaFrame decode(byte[] buf, int offset, int length) throws AmicaProtocolException {
        return AmicaFormat.INSTANCE.decode(buf, offset, length, AmicaProtocolException::new);
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
