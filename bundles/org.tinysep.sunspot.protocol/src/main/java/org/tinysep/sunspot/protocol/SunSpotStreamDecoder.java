package org.tinysep.sunspot.protocol;

import java.util.Objects;

/**
 * Finds Sun SPOT frames in a byte stream, such as the serial link to a basestation that writes framed packets.
 * <p>
 * Bytes are buffered across {@link #accept(byte[], int, int)} calls. A candidate frame starts at the first buffered
 * byte. Once its twelve header bytes are buffered it must have S = L and a known sensor type (2..5, see
 * {@link SunSpotSensorType}); once complete it must pass the checksum and have a payload whose first byte is the
 * sensor type. A valid candidate is emitted and consumed; a failing one loses exactly one byte and the search
 * restarts at the next byte (resynchronisation), so a valid frame right after garbage is still found. An incomplete
 * candidate waits for more bytes. Each run of consecutive dropped bytes is reported once, with the reason seen at
 * its first byte, just before the frame that ends it; a run that reaches {@value #BUFFER_SIZE} bytes is reported
 * then and a new run starts. The buffer never holds more than {@value #BUFFER_SIZE} bytes.
 * <p>
 * Not thread-safe: one reader thread feeds one decoder. Sink callbacks run on that thread, inside {@code accept};
 * they must not call back into this decoder. If a callback throws, the exception leaves {@code accept}, the decoder
 * stays consistent, and the bytes of that call not yet buffered are not processed.
 */
public final class SunSpotStreamDecoder {

    /** Receives what the decoder finds. */
    public interface Sink {

        /** @param f a valid frame, in stream order */
        void frame(SunSpotFrame f);

        /**
         * @param r            the reason seen at the first byte of the dropped run
         * @param skippedBytes how many consecutive bytes were dropped, at least 1
         */
        void rejected(RejectReason r, int skippedBytes);
    }

    /** Capacity of the buffer, in bytes; also the longest run reported in one {@link Sink#rejected} call. */
    public static final int BUFFER_SIZE = 4096;

    private final Sink sink;
    private final byte[] buf = new byte[BUFFER_SIZE];
    private int start;
    private int count;
    private int skipped;
    private RejectReason skipReason;

    /** @param sink receives frames and rejections */
    public SunSpotStreamDecoder(Sink sink) {
        this.sink = Objects.requireNonNull(sink, "sink");
    }

    /**
     * Feeds bytes read from the stream; emits every frame they complete.
     *
     * @param src the bytes read
     * @param off the first new byte
     * @param len the number of new bytes
     * @throws IndexOutOfBoundsException if the range lies outside {@code src}
     */
    public void accept(byte[] src, int off, int len) {
        Objects.checkFromIndexSize(off, len, src.length);
        while (len > 0) {
            if (start > 0) {
                System.arraycopy(buf, start, buf, 0, count);
                start = 0;
            }
            int n = Math.min(len, BUFFER_SIZE - count);
            System.arraycopy(src, off, buf, count, n);
            count += n;
            off += n;
            len -= n;
            drain();
        }
    }

    /**
     * Discards all buffered bytes, e.g. after the link was reopened. Bytes already dropped but not yet reported, and
     * the bytes of an incomplete candidate frame, are reported as one run (reason {@link RejectReason#TRUNCATED} if
     * only an incomplete candidate was buffered). No run is longer than {@value #BUFFER_SIZE}: if the two together
     * exceed it, the first {@value #BUFFER_SIZE} bytes are reported with the run's reason and the rest of the
     * candidate as a second, {@link RejectReason#TRUNCATED} run.
     */
    public void reset() {
        int left = count;
        start = 0;
        count = 0;
        if (skipped == 0 && left > 0) {
            skipReason = RejectReason.TRUNCATED;
        }
        int first = Math.min(left, BUFFER_SIZE - skipped);
        skipped += first;
        left -= first;
        reportRun();
        if (left > 0) {
            skipped = left;
            skipReason = RejectReason.TRUNCATED;
            reportRun();
        }
    }

    /** @return how many bytes are buffered, waiting to complete a candidate frame; at most {@value #BUFFER_SIZE} */
    public int buffered() {
        return count;
    }

    private void drain() {
        while (count >= SunSpotCodec.HEADER_LENGTH) { // the whole header is buffered: the candidate can be judged
            int p = start;
            int size = buf[p + SunSpotCodec.SIZE] & 0xFF;
            if (size != (buf[p + SunSpotCodec.LENGTH] & 0xFF)) {
                drop(RejectReason.LENGTH_MISMATCH);
                continue;
            }
            if (!SunSpotSensorType.isKnown(buf[p + SunSpotCodec.SENSOR_TYPE] & 0xFF)) {
                drop(RejectReason.UNKNOWN_PAYLOAD);
                continue;
            }
            int total = SunSpotCodec.HEADER_LENGTH + size;
            if (count < total) {
                return;
            }
            RejectReason reason = SunSpotCodec.check(buf, p, total);
            if (reason != null) {
                drop(reason);
                continue;
            }
            SunSpotFrame frame = SunSpotCodec.frameAt(buf, p);
            start += total;
            count -= total;
            reportRun();
            sink.frame(frame);
        }
    }

    private void drop(RejectReason reason) {
        if (skipped == 0) {
            skipReason = reason;
        }
        start++;
        count--;
        skipped++;
        if (skipped == BUFFER_SIZE) {
            reportRun();
        }
    }

    private void reportRun() {
        if (skipped > 0) {
            int n = skipped;
            RejectReason r = skipReason;
            skipped = 0;
            skipReason = null;
            sink.rejected(r, n);
        }
    }
}
