package org.tinysep.amica.protocol;

import org.tinysep.link.frame.FrameFormat;
import org.tinysep.link.frame.Hex;

/**
 * The AmICA frame: its header value rule and its header fields (S at 0, then header value, source, destination,
 * netgroup, sequence, CK, L); layout, checks and encoding are {@link FrameFormat}'s.
 */
final class AmicaFormat extends FrameFormat<AmicaFrame, RejectReason> {

    static final int HEADER = 1;
    static final int SOURCE = 2;
    static final int DESTINATION = 3;
    static final int NETGROUP = 4;
    static final int SEQUENCE = 5;
    static final int CHECKSUM = 6;

    static final AmicaFormat INSTANCE = new AmicaFormat();

    private AmicaFormat() {
        super(AmicaCodec.HEADER_LENGTH, CHECKSUM, RejectReason.values(), AmicaFrame::payloadUnsafe);
    }

    @Override
    protected RejectReason headerFault(byte[] buf, int off, int available) {
        return available > HEADER && (buf[off + HEADER] & 0xFF) != AmicaCodec.HEADER_VALUE
                ? RejectReason.BAD_HEADER : null;
    }

    @Override
    protected void writeHeader(AmicaFrame frame, byte[] out) {
        out[HEADER] = (byte) AmicaCodec.HEADER_VALUE;
        out[SOURCE] = (byte) frame.source();
        out[DESTINATION] = (byte) frame.destination();
        out[NETGROUP] = (byte) frame.netgroup();
        out[SEQUENCE] = (byte) frame.sequence();
    }

    @Override
    protected AmicaFrame frameAt(byte[] buf, int off) {
        return new AmicaFrame(buf[off + NETGROUP] & 0xFF, buf[off + SOURCE] & 0xFF, buf[off + DESTINATION] & 0xFF,
                buf[off + SEQUENCE] & 0xFF, payload(buf, off));
    }

    @Override
    protected String familyDetail(RejectReason reason, byte[] buf, int off, int len) {
        return reason == RejectReason.BAD_HEADER
                ? "header value " + Hex.ofByte(buf[off + HEADER] & 0xFF) + ", expected "
                        + Hex.ofByte(AmicaCodec.HEADER_VALUE)
                : "";
    }
}
