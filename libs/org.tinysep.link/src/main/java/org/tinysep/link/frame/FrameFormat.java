package org.tinysep.link.frame;

import java.util.Arrays;
import java.util.Objects;
import java.util.function.Function;

/**
 * The layout and the checks of one protocol family's frames: size identifier S at byte 0, the checksum byte CK
 * directly followed by the payload length L, {@code headerLength} bytes before the payload, at most
 * {@value #MAX_PAYLOAD} payload bytes. CK is the CRC-8/SMBUS of every other byte of the frame. A family subclasses
 * it with its reason enum, its own header rules and its frame record; the order of the checks is the same for both:
 * length, family header rule, S = L, exact length, checksum, family frame rule.
 * <p>
 * Stateless and thread-safe.
 *
 * @param <F> the family's frame
 * @param <R> the family's reject reason
 */
public abstract class FrameFormat<F, R> {

    /** Largest payload, in bytes. */
    public static final int MAX_PAYLOAD = 255;
    /** Index of the size identifier S. */
    public static final int SIZE = 0;

    private final int headerLength;
    private final int checksum;
    private final R truncated;
    private final R oversize;
    private final R lengthMismatch;
    private final R badChecksum;
    private final Function<? super F, byte[]> payloadOf;

    /**
     * @param headerLength   bytes before the payload, S included
     * @param checksumIndex  index of CK; L follows it
     * @param truncated      the family's reason for too few bytes
     * @param oversize       ... for too many bytes
     * @param lengthMismatch ... for S differing from L
     * @param badChecksum    ... for a wrong CK
     * @param payloadOf      the frame's payload, not copied: {@link #encode(Object)} only reads it
     */
    protected FrameFormat(int headerLength, int checksumIndex, R truncated, R oversize, R lengthMismatch,
            R badChecksum, Function<? super F, byte[]> payloadOf) {
        this.headerLength = headerLength;
        this.checksum = checksumIndex;
        this.truncated = Objects.requireNonNull(truncated);
        this.oversize = Objects.requireNonNull(oversize);
        this.lengthMismatch = Objects.requireNonNull(lengthMismatch);
        this.badChecksum = Objects.requireNonNull(badChecksum);
        this.payloadOf = Objects.requireNonNull(payloadOf);
    }

    /**
     * The usual constructor: the four shared reasons are taken by name from the family's reason enum, which names
     * them alike in every family.
     *
     * @param headerLength  bytes before the payload, S included
     * @param checksumIndex index of CK; L follows it
     * @param reasons       the values of the family's reason enum, with TRUNCATED, OVERSIZE, LENGTH_MISMATCH and
     *                      BAD_CHECKSUM among them
     * @param payloadOf     the frame's payload, not copied: {@link #encode(Object)} only reads it
     * @throws IllegalArgumentException if one of the four is missing
     */
    protected FrameFormat(int headerLength, int checksumIndex, R[] reasons, Function<? super F, byte[]> payloadOf) {
        this(headerLength, checksumIndex, named(reasons, "TRUNCATED"), named(reasons, "OVERSIZE"),
                named(reasons, "LENGTH_MISMATCH"), named(reasons, "BAD_CHECKSUM"), payloadOf);
    }

    private static <R> R named(R[] reasons, String name) {
        for (R r : reasons) {
            if (r instanceof Enum<?> e && e.name().equals(name)) {
                return r;
            }
        }
        throw new IllegalArgumentException("the family's reasons have no " + name);
    }

    /**
     * A family rule on the header's fixed bytes, judged as soon as they are buffered (AmICA: the header value).
     *
     * @param available how many bytes of the candidate are buffered, at least 1
     * @return the broken rule, or null if none is broken or the bytes it needs are not yet buffered
     */
    protected R headerFault(byte[] buf, int off, int available) {
        return null;
    }

    /** A family rule a byte stream applies once the whole header is buffered and S = L (Sun SPOT: known type). */
    protected R streamFault(byte[] buf, int off) {
        return null;
    }

    /** A family rule on a complete frame whose checksum is right (Sun SPOT: type = first payload byte). */
    protected R frameFault(byte[] buf, int off, int size) {
        return null;
    }

    /** The detail of a family reason for the exception message; "" if there is none. */
    protected String familyDetail(R reason, byte[] buf, int off, int len) {
        return "";
    }

    /** Builds the frame at {@code off}; the caller has checked it. */
    protected abstract F frameAt(byte[] buf, int off);

    /** @return a copy of the payload of the checked frame at {@code off}, for {@link #frameAt} */
    protected final byte[] payload(byte[] buf, int off) {
        return Arrays.copyOfRange(buf, off + headerLength, off + headerLength + size(buf, off));
    }

    /** Writes the family's header fields of {@code frame} into {@code out}; S, L and CK are written by the caller. */
    protected abstract void writeHeader(F frame, byte[] out);

    /** @return the reason used when bytes of an incomplete frame are discarded */
    public final R truncated() {
        return truncated;
    }

    /** @return the reason used when S differs from L */
    public final R lengthMismatch() {
        return lengthMismatch;
    }

    /** @return bytes before the payload */
    public final int headerLength() {
        return headerLength;
    }

    /** @return the largest frame, in bytes */
    public final int maxFrame() {
        return headerLength + MAX_PAYLOAD;
    }

    /** @return S of the frame at {@code off}, 0..255 */
    public static int size(byte[] buf, int off) {
        return buf[off + SIZE] & 0xFF;
    }

    /** @return true if S equals L in the header at {@code off}; the whole header must be there */
    public final boolean lengthsAgree(byte[] buf, int off) {
        return size(buf, off) == (buf[off + checksum + 1] & 0xFF);
    }

    /** The checksum of the frame at {@code off} with the given payload length: CRC over all bytes but CK. */
    public final int checksum(byte[] buf, int off, int payloadLength) {
        int crc = Crc8.update(0, buf, off, checksum);
        return Crc8.update(crc, buf, off + checksum + 1, 1 + payloadLength);
    }

    /** Writes S, L and CK into a frame whose other header bytes and payload are filled in. */
    public final byte[] seal(byte[] out, int payloadLength) {
        out[SIZE] = (byte) payloadLength;
        out[checksum + 1] = (byte) payloadLength;
        out[checksum] = (byte) checksum(out, 0, payloadLength);
        return out;
    }

    /**
     * Encodes one frame: the family's header fields, the payload after the header, then S, L and CK ({@link #seal}).
     *
     * @return the frame's bytes, {@link #headerLength()} + payload length long
     */
    public final byte[] encode(F frame) {
        byte[] payload = payloadOf.apply(frame);
        byte[] out = new byte[headerLength + payload.length];
        writeHeader(frame, out);
        System.arraycopy(payload, 0, out, headerLength, payload.length);
        return seal(out, payload.length);
    }

    /** @return why the range is not exactly one valid frame, or null if it is */
    public final R check(byte[] buf, int off, int len) {
        if (len < headerLength) {
            return truncated;
        }
        if (len > maxFrame()) {
            return oversize;
        }
        R header = headerFault(buf, off, len);
        if (header != null) {
            return header;
        }
        int size = size(buf, off);
        if (!lengthsAgree(buf, off)) {
            return lengthMismatch;
        }
        if (len < headerLength + size) {
            return truncated;
        }
        if (len > headerLength + size) {
            return oversize;
        }
        if (checksum(buf, off, size) != (buf[off + checksum] & 0xFF)) {
            return badChecksum;
        }
        return frameFault(buf, off, size);
    }

    /**
     * Decodes exactly one frame that occupies the whole range, as in a UDP datagram.
     *
     * @return the frame, or null with the reason passed to {@code rejected}
     * @throws IndexOutOfBoundsException if the range lies outside {@code buf}
     */
    public final <X extends Exception> F decode(byte[] buf, int off, int len, Rejection<R, X> rejected) throws X {
        Objects.checkFromIndexSize(off, len, buf.length);
        R reason = check(buf, off, len);
        if (reason != null) {
            throw rejected.exception(reason, detail(reason, buf, off, len));
        }
        return frameAt(buf, off);
    }

    /** Makes the family's protocol exception. */
    @FunctionalInterface
    public interface Rejection<R, X extends Exception> {
        X exception(R reason, String detail);
    }

    /** @return what exactly was wrong with the range, e.g. {@code "checksum 0x12, computed 0x34"} */
    public final String detail(R reason, byte[] buf, int off, int len) {
        int size = len > SIZE ? size(buf, off) : 0;
        if (reason == truncated) {
            return len < headerLength
                    ? len + " bytes, a frame has at least " + headerLength
                    : len + " bytes, size identifier " + size + " announces " + (headerLength + size);
        }
        if (reason == oversize) {
            return len > maxFrame()
                    ? len + " bytes, a frame has at most " + maxFrame()
                    : len + " bytes, size identifier " + size + " announces " + (headerLength + size);
        }
        if (reason == lengthMismatch) {
            return "size identifier " + size + ", payload length " + (buf[off + checksum + 1] & 0xFF);
        }
        if (reason == badChecksum) {
            return "checksum " + Hex.ofByte(buf[off + checksum] & 0xFF) + ", computed "
                    + Hex.ofByte(checksum(buf, off, size));
        }
        return familyDetail(reason, buf, off, len);
    }

    /**
     * The message of a family's protocol exception: {@code "NAME (description): detail"}, without the detail part
     * when there is none.
     */
    public static String message(Enum<?> reason, String description, String detail) {
        Objects.requireNonNull(reason, "reason");
        String head = reason.name() + " (" + description + ")";
        return detail == null || detail.isEmpty() ? head : head + ": " + detail;
    }
}
