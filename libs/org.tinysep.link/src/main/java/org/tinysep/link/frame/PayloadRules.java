package org.tinysep.link.frame;

import java.util.Objects;

/**
 * What the payload codecs of both protocol families share, written once: a payload is named by its first two bytes
 * (its type), lengths are exact, and the 4-byte status payload is {@code type, 0, value} with its value in range.
 * Each family keeps only its payload table ({@code AmicaPayloads}, {@code SunSpotPayloads}) and makes one instance
 * with its reasons and its exception. Multi-byte numbers are big-endian. Stateless and thread-safe.
 *
 * @param <R> the family's reject reason
 * @param <X> the family's protocol exception
 */
public final class PayloadRules<R, X extends Exception> {

    /** Length of a status payload: type (2 bytes), reserved 0, value. */
    public static final int STATUS_LENGTH = 4;

    private final R unknownPayload;
    private final R badValue;
    private final FrameFormat.Rejection<R, X> rejected;

    /**
     * @param unknownPayload the family's reason for a payload whose type is not in its table
     * @param badValue       ... for a wrong length, a non-zero reserved byte or a value out of range
     * @param rejected       makes the family's protocol exception
     */
    public PayloadRules(R unknownPayload, R badValue, FrameFormat.Rejection<R, X> rejected) {
        this.unknownPayload = Objects.requireNonNull(unknownPayload);
        this.badValue = Objects.requireNonNull(badValue);
        this.rejected = Objects.requireNonNull(rejected);
    }

    /** @return the type named by the two bytes, for comparing with {@link #typeOf(byte[])} */
    public static int type(int first, int second) {
        return first << 8 | second;
    }

    /**
     * @return the payload's type, its first two bytes
     * @throws X with the unknown-payload reason if it is shorter than two bytes
     */
    public int typeOf(byte[] payload) throws X {
        Objects.requireNonNull(payload, "payload");
        if (payload.length < 2) {
            throw rejected.exception(unknownPayload, payload.length + "-byte payload cannot name a payload type");
        }
        return type(payload[0] & 0xFF, payload[1] & 0xFF);
    }

    /** @return the exception for a payload whose type is not in the family's table */
    public X unknown(byte[] payload) {
        return rejected.exception(unknownPayload, "payload type " + (payload[0] & 0xFF) + " " + (payload[1] & 0xFF)
                + " (payload " + Hex.of(payload, 0, payload.length) + ")");
    }

    /** @return the exception for a known payload with a wrong value, e.g. {@code "light status value 101, ..."} */
    public X badValue(String detail) {
        return rejected.exception(badValue, detail);
    }

    /** @throws X with the bad-value reason unless the payload has exactly {@code expected} bytes */
    public void checkLength(String name, byte[] p, int expected) throws X {
        if (p.length != expected) {
            throw badValue(name + " payload has " + p.length + " bytes, expected " + expected);
        }
    }

    /**
     * Checks a payload's length and its reserved third byte.
     *
     * @return its fourth byte, 0..255
     */
    public int statusValue(String name, byte[] p, int length) throws X {
        checkLength(name, p, length);
        if (p[2] != 0) {
            throw badValue(name + " payload third byte is " + (p[2] & 0xFF) + ", expected 0");
        }
        return p[3] & 0xFF;
    }

    /** @return the status value as a flag; 0 or 1, anything else is a bad value */
    public boolean flag(String name, byte[] p, int length) throws X {
        int v = statusValue(name, p, length);
        if (v > 1) {
            throw badValue(name + " value " + v + ", expected 0 or 1");
        }
        return v == 1;
    }

    /** @return the value of a 4-byte status payload as a percentage; above 100 is a bad value */
    public int percent(String name, byte[] p) throws X {
        int v = statusValue(name, p, STATUS_LENGTH);
        if (v > 100) {
            throw badValue(name + " value " + v + ", expected 0..100");
        }
        return v;
    }

    /** @return a 4-byte status payload: type, 0, value */
    public static byte[] status(int type, int value) {
        return new byte[] {(byte) (type >>> 8), (byte) type, 0, (byte) value};
    }

    /** @return the unsigned 16-bit number at {@code off} */
    public static int u16(byte[] b, int off) {
        return (b[off] & 0xFF) << 8 | b[off + 1] & 0xFF;
    }

    /** @return the signed 16-bit number at {@code off} */
    public static int s16(byte[] b, int off) {
        return (short) u16(b, off);
    }

    /** @return the unsigned 32-bit number at {@code off} */
    public static long u32(byte[] b, int off) {
        return (long) u16(b, off) << 16 | u16(b, off + 2);
    }

    /** Writes the low 16 bits of {@code v} at {@code off}. */
    public static void putU16(byte[] b, int off, int v) {
        b[off] = (byte) (v >>> 8);
        b[off + 1] = (byte) v;
    }

    /** Writes the low 32 bits of {@code v} at {@code off}. */
    public static void putU32(byte[] b, int off, long v) {
        putU16(b, off, (int) (v >>> 16));
        putU16(b, off + 2, (int) v);
    }
}
