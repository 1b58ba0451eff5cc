package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.FrameFormat;

/**
 * The Sun SPOT frame: its 8-byte source address (bytes 1 to 8, most significant first) and sensor type (byte 9),
 * the stream's known-type rule and the type rule; layout, checks and encoding are {@link FrameFormat}'s.
 */
final class SunSpotFormat extends FrameFormat<SunSpotFrame, RejectReason> {

    static final int SOURCE = 1;
    static final int ADDRESS_LENGTH = 8;
    static final int SENSOR_TYPE = SOURCE + ADDRESS_LENGTH;
    static final int CHECKSUM = SENSOR_TYPE + 1;

    static final SunSpotFormat INSTANCE = new SunSpotFormat();

    private SunSpotFormat() {
        super(SunSpotCodec.HEADER_LENGTH, CHECKSUM, RejectReason.values(), SunSpotFrame::payloadUnsafe);
    }

    @Override
    protected RejectReason streamFault(byte[] buf, int off) {
        return SunSpotSensorType.isKnown(buf[off + SENSOR_TYPE] & 0xFF) ? null : RejectReason.UNKNOWN_PAYLOAD;
    }

    @Override
    protected RejectReason frameFault(byte[] buf, int off, int size) {
        return size == 0 || buf[off + SunSpotCodec.HEADER_LENGTH] != buf[off + SENSOR_TYPE]
                ? RejectReason.TYPE_MISMATCH : null;
    }

    @Override
    protected void writeHeader(SunSpotFrame frame, byte[] out) {
        long address = frame.source().value();
        for (int i = 0; i < ADDRESS_LENGTH; i++) {
            out[SOURCE + i] = (byte) (address >>> (8 * (ADDRESS_LENGTH - 1 - i)));
        }
        out[SENSOR_TYPE] = (byte) frame.sensorType();
    }

    @Override
    protected SunSpotFrame frameAt(byte[] buf, int off) {
        long address = 0;
        for (int i = 0; i < ADDRESS_LENGTH; i++) {
            address = address << 8 | buf[off + SOURCE + i] & 0xFF;
        }
        return new SunSpotFrame(new SunSpotAddress(address), buf[off + SENSOR_TYPE] & 0xFF, payload(buf, off));
    }

    @Override
    protected String familyDetail(RejectReason reason, byte[] buf, int off, int len) {
        if (reason != RejectReason.TYPE_MISMATCH) {
            return "";
        }
        int type = buf[off + SENSOR_TYPE] & 0xFF;
        return size(buf, off) == 0
                ? "sensor type " + type + ", empty payload"
                : "sensor type " + type + ", payload starts with " + (buf[off + SunSpotCodec.HEADER_LENGTH] & 0xFF);
    }
}
