package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.FrameCodec;

/**
 * Encodes and decodes one Sun SPOT frame (thesis Figure 3.15): size identifier S, the eleven header bytes (source
 * address, sensor type, checksum, payload length L) and S payload bytes. See {@code docs/protocols/sunspot.md} for
 * the byte layout and the checksum.
 * <p>
 * The layout, the checks, {@link #MAX_PAYLOAD} and {@link #crc8(byte[], int, int)} are shared with the AmICA
 * protocol ({@code org.tinysep.link.frame.FrameCodec} and {@code FrameFormat}); this family adds its address, its
 * sensor type and the type rule ({@code SunSpotFormat}).
 * <p>
 * Stateless and thread-safe. For byte streams (serial links) use {@link SunSpotStreamDecoder}.
 */
public final class SunSpotCodec extends FrameCodec {

    /** Bytes before the payload: size identifier plus the eleven header bytes. */
    public static final int HEADER_LENGTH = 12;
    /** Largest frame, in bytes: {@link #HEADER_LENGTH} + {@link #MAX_PAYLOAD}. */
    public static final int MAX_FRAME = HEADER_LENGTH + MAX_PAYLOAD;

    private SunSpotCodec() {
    }

    /**
     * @param frame the frame
     * @return the frame's bytes, {@link #HEADER_LENGTH} + payload length long, checksum filled in
     */
    public static byte[] encode(SunSpotFrame frame) {
        return SunSpotFormat.INSTANCE.encode(frame);
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
}
