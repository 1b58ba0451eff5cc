package org.tinysep.sunspot.protocol;

import java.util.Objects;
import org.tinysep.link.frame.Hex;

/**
 * Converts between payload bytes (thesis Table 3.2, plus Movement Detection version 2) and {@link SunSpotPayload}
 * records. A payload is named by its first two bytes: the sensor type and the payload version. Lengths are exact
 * (10 bytes for Movement Detection version 2, 4 for the others), the third byte is 0 where the table shows it, and
 * values must be in range. Multi-byte numbers are signed 16-bit big-endian. Stateless and thread-safe.
 */
public final class SunSpotPayloads {

    /** Length of every version 1 payload. */
    public static final int STATUS_LENGTH = 4;
    /** Length of a Movement Detection version 2 payload (with coordinates). */
    public static final int MOVEMENT_V2_LENGTH = 10;

    private static final int MOVEMENT_V1 = type(2, 1);
    private static final int MOVEMENT_V2 = type(2, 2);
    private static final int TEMPERATURE = type(3, 1);
    private static final int LIGHT = type(4, 1);
    private static final int PET_MOVEMENT = type(5, 1);
    private static final int MIN_TENTHS = -400;
    private static final int MAX_TENTHS = 1250;

    private SunSpotPayloads() {
    }

    /**
     * @param payload a frame's payload
     * @return the decoded payload
     * @throws SunSpotProtocolException {@link RejectReason#UNKNOWN_PAYLOAD} if the payload is shorter than two bytes
     *                                  or its first two bytes name no known payload; {@link RejectReason#BAD_VALUE}
     *                                  if a known payload has a wrong length, a non-zero third byte or a value out
     *                                  of range
     */
    public static SunSpotPayload decode(byte[] payload) throws SunSpotProtocolException {
        Objects.requireNonNull(payload, "payload");
        if (payload.length < 2) {
            throw new SunSpotProtocolException(RejectReason.UNKNOWN_PAYLOAD,
                    payload.length + "-byte payload cannot name a payload type");
        }
        int type = type(payload[0] & 0xFF, payload[1] & 0xFF);
        if (type == MOVEMENT_V1) {
            return new MovementDetection(flag("movement detection", payload, STATUS_LENGTH));
        }
        if (type == MOVEMENT_V2) {
            boolean detected = flag("movement detection v2", payload, MOVEMENT_V2_LENGTH);
            return new MovementDetection(detected, new Position(s16(payload, 4), s16(payload, 6), s16(payload, 8)));
        }
        if (type == TEMPERATURE) {
            checkLength("temperature status", payload, STATUS_LENGTH);
            int tenths = s16(payload, 2);
            if (tenths < MIN_TENTHS || tenths > MAX_TENTHS) {
                throw new SunSpotProtocolException(RejectReason.BAD_VALUE,
                        "temperature status value " + tenths + " tenths of a degree, expected -400..1250");
            }
            return TemperatureStatus.ofTenths(tenths);
        }
        if (type == LIGHT) {
            int v = statusValue("light status", payload, STATUS_LENGTH);
            if (v > 100) {
                throw new SunSpotProtocolException(RejectReason.BAD_VALUE,
                        "light status value " + v + ", expected 0..100");
            }
            return new LightStatus(v);
        }
        if (type == PET_MOVEMENT) {
            return new PetMovementDetection(flag("pet movement detection", payload, STATUS_LENGTH));
        }
        throw new SunSpotProtocolException(RejectReason.UNKNOWN_PAYLOAD,
                "payload type " + (payload[0] & 0xFF) + " " + (payload[1] & 0xFF) + " (payload "
                        + Hex.of(payload, 0, payload.length) + ")");
    }

    /**
     * @param payload a payload
     * @return its bytes: 10 for a {@link MovementDetection} with a position, 4 for the others
     */
    public static byte[] encode(SunSpotPayload payload) {
        Objects.requireNonNull(payload, "payload");
        if (payload instanceof MovementDetection m) {
            if (m.position() == null) {
                return status(MOVEMENT_V1, m.detected() ? 1 : 0);
            }
            byte[] b = new byte[MOVEMENT_V2_LENGTH];
            b[0] = (byte) (MOVEMENT_V2 >>> 8);
            b[1] = (byte) MOVEMENT_V2;
            b[3] = (byte) (m.detected() ? 1 : 0);
            putS16(b, 4, m.position().xCentimetres());
            putS16(b, 6, m.position().yCentimetres());
            putS16(b, 8, m.position().zCentimetres());
            return b;
        }
        if (payload instanceof TemperatureStatus t) {
            byte[] b = status(TEMPERATURE, 0);
            putS16(b, 2, t.tenths());
            return b;
        }
        if (payload instanceof LightStatus l) {
            return status(LIGHT, l.percent());
        }
        PetMovementDetection p = (PetMovementDetection) payload; // the interface is sealed: nothing else remains
        return status(PET_MOVEMENT, p.detected() ? 1 : 0);
    }

    private static int type(int first, int second) {
        return first << 8 | second;
    }

    private static byte[] status(int type, int value) {
        return new byte[] {(byte) (type >>> 8), (byte) type, 0, (byte) value};
    }

    private static void checkLength(String name, byte[] p, int expected) throws SunSpotProtocolException {
        if (p.length != expected) {
            throw new SunSpotProtocolException(RejectReason.BAD_VALUE,
                    name + " payload has " + p.length + " bytes, expected " + expected);
        }
    }

    /** Checks a payload's length and its reserved third byte; returns its fourth byte. */
    private static int statusValue(String name, byte[] p, int length) throws SunSpotProtocolException {
        checkLength(name, p, length);
        if (p[2] != 0) {
            throw new SunSpotProtocolException(RejectReason.BAD_VALUE,
                    name + " payload third byte is " + (p[2] & 0xFF) + ", expected 0");
        }
        return p[3] & 0xFF;
    }

    private static boolean flag(String name, byte[] p, int length) throws SunSpotProtocolException {
        int v = statusValue(name, p, length);
        if (v > 1) {
            throw new SunSpotProtocolException(RejectReason.BAD_VALUE, name + " value " + v + ", expected 0 or 1");
        }
        return v == 1;
    }

    private static int s16(byte[] b, int off) {
        return (short) ((b[off] & 0xFF) << 8 | b[off + 1] & 0xFF);
    }

    private static void putS16(byte[] b, int off, int v) {
        b[off] = (byte) (v >>> 8);
        b[off + 1] = (byte) v;
    }
}
