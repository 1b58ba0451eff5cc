package org.tinysep.amica.protocol;

import java.util.Arrays;
import org.tinysep.link.frame.FrameFormat;
import org.tinysep.link.frame.Hex;

/** The AmICA frame: its header value rule and its header fields; layout and checks are {@link FrameFormat}'s. */
final class AmicaFormat extends FrameFormat<AmicaFrame, RejectReason> {

    static final AmicaFormat INSTANCE = new AmicaFormat();

    private AmicaFormat() {
        super(AmicaCodec.HEADER_LENGTH, AmicaCodec.CHECKSUM, RejectReason.TRUNCATED, RejectReason.OVERSIZE,
                RejectReason.LENGTH_MISMATCH, RejectReason.BAD_CHECKSUM);
    }

    @Override
    protected RejectReason headerFault(byte[] buf, int off, int available) {
        return available > AmicaCodec.HEADER && (buf[off + AmicaCodec.HEADER] & 0xFF) != AmicaCodec.HEADER_VALUE
                ? RejectReason.BAD_HEADER : null;
    }

    @Override
    protected AmicaFrame frameAt(byte[] buf, int off) {
        int size = size(buf, off);
        byte[] payload = Arrays.copyOfRange(buf, off + AmicaCodec.HEADER_LENGTH, off + AmicaCodec.HEADER_LENGTH + size);
        return new AmicaFrame(buf[off + AmicaCodec.NETGROUP] & 0xFF, buf[off + AmicaCodec.SOURCE] & 0xFF,
                buf[off + AmicaCodec.DESTINATION] & 0xFF, buf[off + AmicaCodec.SEQUENCE] & 0xFF, payload);
    }

    @Override
    protected String familyDetail(RejectReason reason, byte[] buf, int off, int len) {
        return reason == RejectReason.BAD_HEADER
                ? "header value " + Hex.ofByte(buf[off + AmicaCodec.HEADER] & 0xFF) + ", expected "
                        + Hex.ofByte(AmicaCodec.HEADER_VALUE)
                : "";
    }
}
