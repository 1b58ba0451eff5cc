package org.tinysep.amica.protocol;

import org.tinysep.link.frame.FrameCodec;

/**
 * Encodes and decodes one AmICA frame: size identifier S, the seven header bytes (header value, source,
 * destination, netgroup, sequence, checksum, payload length L) and S payload bytes. See
 * {@code docs/protocols/amica.md} for the byte layout and the checksum.
 * <p>
 * The layout, the checks, {@link #MAX_PAYLOAD} and {@link #crc8(byte[], int, int)} are shared with the Sun SPOT
 * protocol ({@code org.tinysep.link.frame.FrameCodec} and {@code FrameFormat}); this family adds the header value
 * and its header fields ({@code AmicaFormat}).
 * <p>
 * Stateless and thread-safe. For byte streams (serial links) use {@link AmicaStreamDecoder}.
 */
public final class AmicaCodec extends FrameCodec {

    /** Header value of AmICA node protocol v1; frames with another value are rejected. */
    public static final int HEADER_VALUE = 0xA1;
    /** Bytes before the payload: size identifier plus the seven header bytes. */
    public static final int HEADER_LENGTH = 8;
    /** Largest frame, in bytes: {@link #HEADER_LENGTH} + {@link #MAX_PAYLOAD}. */
    public static final int MAX_FRAME = HEADER_LENGTH + MAX_PAYLOAD;
    /** Address of the platform (base station) within every netgroup. */
    public static final int PLATFORM_ADDRESS = 0;

    private AmicaCodec() {
    }

    /**
     * @param frame the frame
     * @return the frame's bytes, {@link #HEADER_LENGTH} + payload length long, checksum filled in
     */
    public static byte[] encode(AmicaFrame frame) {
        return AmicaFormat.INSTANCE.encode(frame);
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
}
