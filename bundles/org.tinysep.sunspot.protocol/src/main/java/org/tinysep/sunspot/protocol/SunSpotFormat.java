package org.tinysep.sunspot.protocol;

import java.util.Arrays;
import org.tinysep.link.frame.FrameFormat;

/**
 * The Sun SPOT frame: its 8-byte source address and sensor type, the stream's known-type rule and the type rule;
 * layout and checks are {@link FrameFormat}'s.
 */
final class SunSpotFormat extends FrameFormat<SunSpotFrame, RejectReason> {

    static final SunSpotFormat INSTANCE = new SunSpotFormat();

    private SunSpotFormat() {
        super(SunSpotCodec.HEADER_LENGTH, SunSpotCodec.CHECKSUM, RejectReason.TRUNCATED, RejectReason.OVERSIZE,
                RejectReason.LENGTH_MISMATCH, RejectReason.BAD_CHECKSUM);
    }

    @Override
    protected RejectReason streamFault(byte[] buf, int off) {
        return SunSpotSensorType.isKnown(buf[off + SunSpotCodec.SENSOR_TYPE] & 0xFF) ? null
                : RejectReason.UNKNOWN_PAYLOAD;
    }

    @Override
    protected RejectReason frameFault(byte[] buf, int off, int size) {
        return size == 0 || buf[off + SunSpotCodec.HEADER_LENGTH] != buf[off + SunSpotCodec.SENSOR_TYPE]
                ? RejectReason.TYPE_MISMATCH : null;
    }

    @Override
    protected SunSpotFrame frameAt(byte[] buf, int off) {
        int size = size(buf, off);
        long address = 0;
        for (int i = 0; i < SunSpotCodec.ADDRESS_LENGTH; i++) {
            address = address << 8 | buf[off + SunSpotCodec.SOURCE + i] & 0xFF;
        }
        byte[] payload = Arrays.copyOfRange(buf, off + SunSpotCodec.HEADER_LENGTH,
                off + SunSpotCodec.HEADER_LENGTH + size);
        return new SunSpotFrame(new SunSpotAddress(address), buf[off + SunSpotCodec.SENSOR_TYPE] & 0xFF, payload);
    }

    @Override
    protected String familyDetail(RejectReason reason, byte[] buf, int off, int len) {
        if (reason != RejectReason.TYPE_MISMATCH) {
            return "";
        }
        int type = buf[off + SunSpotCodec.SENSOR_TYPE] & 0xFF;
        return size(buf, off) == 0
                ? "sensor type " + type + ", empty payload"
                : "sensor type " + type + ", payload starts with " + (buf[off + SunSpotCodec.HEADER_LENGTH] & 0xFF);
    }
}
