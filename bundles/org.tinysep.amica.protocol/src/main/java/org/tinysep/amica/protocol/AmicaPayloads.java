package org.tinysep.amica.protocol;

import java.util.Objects;

/**
 * Converts between payload bytes (thesis Table 3.1) and {@link AmicaPayload} records. The payload type is named by
 * its first two bytes; lengths are exact (16 for a keep-alive, 4 for the others), the third byte of a 4-byte payload
 * must be 0 and its value byte must be in range. Multi-byte numbers are big-endian. Stateless and thread-safe.
 */
public final class AmicaPayloads {

    /** Length of a Keep Alive payload. */
    public static final int KEEP_ALIVE_LENGTH = 16;
    /** Length of every other payload. */
    public static final int STATUS_LENGTH = 4;

    private static final int KEEP_ALIVE = type(82, 0);
    private static final int REED_SWITCH = type(100, 3);
    private static final int MOTION = type(100, 5);
    private static final int LIGHT = type(5, 2);
    private static final int SPEAKER = type(5, 4);
    private static final int HEATER = type(5, 8);

    private AmicaPayloads() {
    }

    /**
     * @param payload a frame's payload
     * @return the decoded payload
     * @throws AmicaProtocolException {@link RejectReason#UNKNOWN_PAYLOAD} if the payload is shorter than two bytes
     *                                or its first two bytes name no known payload; {@link RejectReason#BAD_VALUE}
     *                                if a known payload has a wrong length, a non-zero third byte or a value out of
     *                                range
     */
    public static AmicaPayload decode(byte[] payload) throws AmicaProtocolException {
        Objects.requireNonNull(payload, "payload");
        if (payload.length < 2) {
            throw new AmicaProtocolException(RejectReason.UNKNOWN_PAYLOAD,
                    payload.length + "-byte payload cannot name a payload type");
        }
        int type = type(payload[0] & 0xFF, payload[1] & 0xFF);
        if (type == KEEP_ALIVE) {
            checkLength("keep-alive", payload, KEEP_ALIVE_LENGTH);
            return new KeepAlive(u32(payload, 2), u16(payload, 6), u16(payload, 8), u16(payload, 10),
                    u32(payload, 12));
        }
        if (type == REED_SWITCH) {
            return new ReedSwitchStatus(flag("reed-switch status", payload));
        }
        if (type == MOTION) {
            return new MotionDetection(flag("motion detection", payload));
        }
        if (type == LIGHT) {
            return new LightControl(percent("light control", payload));
        }
        if (type == SPEAKER) {
            return new SpeakerControl(percent("speaker control", payload));
        }
        if (type == HEATER) {
            return new HeaterControl(percent("heater control", payload));
        }
        throw new AmicaProtocolException(RejectReason.UNKNOWN_PAYLOAD,
                "payload type " + (payload[0] & 0xFF) + " " + (payload[1] & 0xFF) + " (payload "
                        + Hex.of(payload, 0, payload.length) + ")");
    }

    /**
     * @param payload a payload
     * @return its bytes: 16 for a {@link KeepAlive}, 4 for the others
     */
    public static byte[] encode(AmicaPayload payload) {
        Objects.requireNonNull(payload, "payload");
        if (payload instanceof KeepAlive k) {
            byte[] b = new byte[KEEP_ALIVE_LENGTH];
            b[0] = (byte) (KEEP_ALIVE >>> 8);
            putU32(b, 2, k.uptimeSeconds());
            putU16(b, 6, k.batteryMillivolts());
            putU16(b, 8, k.vendorId());
            putU16(b, 10, k.productId());
            putU32(b, 12, k.serialNumber());
            return b;
        }
        if (payload instanceof ReedSwitchStatus r) {
            return status(REED_SWITCH, r.open() ? 1 : 0);
        }
        if (payload instanceof MotionDetection m) {
            return status(MOTION, m.detected() ? 1 : 0);
        }
        if (payload instanceof LightControl l) {
            return status(LIGHT, l.percent());
        }
        if (payload instanceof SpeakerControl s) {
            return status(SPEAKER, s.percent());
        }
        HeaterControl h = (HeaterControl) payload; // the interface is sealed: nothing else remains
        return status(HEATER, h.percent());
    }

    private static int type(int first, int second) {
        return first << 8 | second;
    }

    private static byte[] status(int type, int value) {
        return new byte[] {(byte) (type >>> 8), (byte) type, 0, (byte) value};
    }

    private static void checkLength(String name, byte[] p, int expected) throws AmicaProtocolException {
        if (p.length != expected) {
            throw new AmicaProtocolException(RejectReason.BAD_VALUE,
                    name + " payload has " + p.length + " bytes, expected " + expected);
        }
    }

    /** Checks a 4-byte payload's length and reserved byte; returns its value byte. */
    private static int statusValue(String name, byte[] p) throws AmicaProtocolException {
        checkLength(name, p, STATUS_LENGTH);
        if (p[2] != 0) {
            throw new AmicaProtocolException(RejectReason.BAD_VALUE,
                    name + " payload third byte is " + (p[2] & 0xFF) + ", expected 0");
        }
        return p[3] & 0xFF;
    }

    private static boolean flag(String name, byte[] p) throws AmicaProtocolException {
        int v = statusValue(name, p);
        if (v > 1) {
            throw new AmicaProtocolException(RejectReason.BAD_VALUE, name + " value " + v + ", expected 0 or 1");
        }
        return v == 1;
    }

    private static int percent(String name, byte[] p) throws AmicaProtocolException {
        int v = statusValue(name, p);
        if (v > Percent.MAX) {
            throw new AmicaProtocolException(RejectReason.BAD_VALUE, name + " value " + v + ", expected 0..100");
        }
        return v;
    }

    private static int u16(byte[] b, int off) {
        return (b[off] & 0xFF) << 8 | b[off + 1] & 0xFF;
    }

    private static long u32(byte[] b, int off) {
        return (long) u16(b, off) << 16 | u16(b, off + 2);
    }

    private static void putU16(byte[] b, int off, int v) {
        b[off] = (byte) (v >>> 8);
        b[off + 1] = (byte) v;
    }

    private static void putU32(byte[] b, int off, long v) {
        putU16(b, off, (int) (v >>> 16));
        putU16(b, off + 2, (int) v);
    }
}
