package org.tinysep.sunspot.protocol;

import java.util.Arrays;
import java.util.Objects;
import org.tinysep.link.frame.Hex;

/**
 * One Sun SPOT frame, decoded: source address, sensor type and payload. The framing bytes (size identifier,
 * checksum, payload length) are derived by {@link SunSpotCodec#encode(SunSpotFrame)}.
 * <p>
 * Immutable: the payload is copied on construction and on access; {@code equals}, {@code hashCode} and
 * {@code toString} use the payload's content. The record does not require {@code sensorType} to equal the
 * payload's first byte, so that tests can build frames the decoder must reject ({@link RejectReason#TYPE_MISMATCH}).
 *
 * @param source     the sending node's address
 * @param sensorType the header's sensor type byte, 0..255 (see {@link SunSpotSensorType})
 * @param payload    the payload (thesis Table 3.2), at most {@value SunSpotCodec#MAX_PAYLOAD} bytes
 */
public record SunSpotFrame(SunSpotAddress source, int sensorType, byte[] payload) {

    /** @throws IllegalArgumentException if a field is out of range; NullPointerException if one is null */
    public SunSpotFrame {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(payload, "payload");
        if (sensorType < 0 || sensorType > 255) {
            throw new IllegalArgumentException("sensorType " + sensorType + " is outside 0..255");
        }
        if (payload.length > SunSpotCodec.MAX_PAYLOAD) {
            throw new IllegalArgumentException(
                    "payload of " + payload.length + " bytes exceeds " + SunSpotCodec.MAX_PAYLOAD);
        }
        payload = payload.clone();
    }

    /**
     * A frame whose sensor type is taken from the payload's first byte, as a node sends it.
     *
     * @param source  the sending node
     * @param payload the payload, at least one byte
     * @return the frame
     * @throws IllegalArgumentException if the payload is empty or too long
     */
    public static SunSpotFrame of(SunSpotAddress source, byte[] payload) {
        if (payload.length == 0) {
            throw new IllegalArgumentException("an empty payload has no sensor type");
        }
        return new SunSpotFrame(source, payload[0] & 0xFF, payload);
    }

    /** @return a copy of the payload */
    @Override
    public byte[] payload() {
        return payload.clone();
    }

    /** @return the payload length in bytes, without copying the payload */
    public int payloadLength() {
        return payload.length;
    }

    /** The payload itself, not a copy, for the codec; callers must not modify it. */
    byte[] payloadUnsafe() {
        return payload;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof SunSpotFrame f && source.equals(f.source) && sensorType == f.sensorType
                && Arrays.equals(payload, f.payload);
    }

    @Override
    public int hashCode() {
        return Objects.hash(source, sensorType) * 31 + Arrays.hashCode(payload);
    }

    /** @return e.g. {@code SunSpotFrame[0014.4F01.0000.1234, type=2, payload=02 01 00 01]} */
    @Override
    public String toString() {
        return "SunSpotFrame[" + source + ", type=" + sensorType + ", payload=" + Hex.of(payload, 0, payload.length)
                + "]";
    }
}
