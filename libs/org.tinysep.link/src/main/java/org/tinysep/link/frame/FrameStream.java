package org.tinysep.link.frame;

import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.ObjIntConsumer;

/**
 * Finds the frames of one {@link FrameFormat} in a byte stream, such as a serial link.
 * <p>
 * Bytes are buffered across {@link #accept(byte[], int, int)} calls. A candidate frame starts at the first buffered
 * byte. It is judged by the format's header rule as soon as the bytes it needs are buffered, then, once the whole
 * header is buffered, by S = L and the format's stream rule, and once complete by the format's full check. A valid
 * candidate is emitted and consumed; a failing one loses exactly one byte and the search restarts at the next byte
 * (resynchronisation), so a valid frame right after garbage is still found. An incomplete candidate waits for more
 * bytes. Each run of consecutive dropped bytes is reported once, with the reason seen at its first byte, just before
 * the frame that ends it; a run that reaches {@value #BUFFER_SIZE} bytes is reported then and a new run starts, so
 * an endless stream of garbage is still reported. The buffer never holds more than {@value #BUFFER_SIZE} bytes.
 * <p>
 * Not thread-safe: one reader thread feeds one stream. The callbacks run on that thread, inside {@code accept};
 * they must not call back into this stream. If a callback throws, the exception leaves {@code accept}, the stream
 * stays consistent, and the bytes of that call not yet buffered are not processed.
 *
 * <p>
 * Each family's public decoder ({@code AmicaStreamDecoder}, {@code SunSpotStreamDecoder}) is this class with its
 * format and its own sink type; the methods are final.
 *
 * @param <F> the frame
 * @param <R> the reject reason
 */
public class FrameStream<F, R> {

    /** Capacity of the buffer, in bytes; also the longest run reported at once. */
    public static final int BUFFER_SIZE = 4096;

    private final FrameFormat<F, R> format;
    private final Consumer<? super F> frames;
    private final ObjIntConsumer<? super R> rejections;
    private final byte[] buf = new byte[BUFFER_SIZE];
    private int start;
    private int count;
    private int skipped;
    private R skipReason;

    /**
     * Receives what a stream finds (a family's decoder names its own {@code Sink} that extends this one).
     *
     * @param <F> the frame
     * @param <R> the reject reason
     */
    public interface Sink<F, R> {

        /** @param f a valid frame, in stream order */
        void frame(F f);

        /**
         * @param r            the reason seen at the first byte of the dropped run
         * @param skippedBytes how many consecutive bytes were dropped, at least 1
         */
        void rejected(R r, int skippedBytes);
    }

    /** @param sink receives frames and rejections (not null) */
    protected FrameStream(FrameFormat<F, R> format, Sink<F, R> sink) {
        this(format, Objects.requireNonNull(sink, "sink")::frame, sink::rejected);
    }

    /**
     * @param format     the frames to find
     * @param frames     receives each valid frame, in stream order
     * @param rejections receives each dropped run: the reason seen at its first byte and how many consecutive bytes
     *                   were dropped, at least 1
     */
    public FrameStream(FrameFormat<F, R> format, Consumer<? super F> frames, ObjIntConsumer<? super R> rejections) {
        this.format = Objects.requireNonNull(format, "format");
        this.frames = Objects.requireNonNull(frames, "frames");
        this.rejections = Objects.requireNonNull(rejections, "rejections");
    }

    /**
     * Feeds bytes read from the stream; emits every frame they complete.
     *
     * @throws IndexOutOfBoundsException if the range lies outside {@code src}
     */
    public final void accept(byte[] src, int off, int len) {
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
     * the bytes of an incomplete candidate frame, are reported as one run (reason {@link FrameFormat#truncated()} if
     * only an incomplete candidate was buffered). No run is longer than {@value #BUFFER_SIZE}: if the two together
     * exceed it, the first {@value #BUFFER_SIZE} bytes are reported with the run's reason and the rest of the
     * candidate as a second, truncated run.
     */
    public final void reset() {
        int left = count;
        start = 0;
        count = 0;
        if (skipped == 0 && left > 0) {
            skipReason = format.truncated();
        }
        int first = Math.min(left, BUFFER_SIZE - skipped);
        skipped += first;
        left -= first;
        reportRun();
        if (left > 0) { // fewer than BUFFER_SIZE: skipped was below it, count at most BUFFER_SIZE
            skipped = left;
            skipReason = format.truncated();
            reportRun();
        }
    }

    /** @return how many bytes are buffered, waiting to complete a candidate frame; at most {@value #BUFFER_SIZE} */
    public final int buffered() {
        return count;
    }

    private void drain() {
        int header = format.headerLength();
        while (count > 0) {
            int p = start;
            R reason = format.headerFault(buf, p, count);
            if (reason != null) {
                drop(reason);
                continue;
            }
            if (count < header) {
                return;
            }
            if (!format.lengthsAgree(buf, p)) {
                drop(format.lengthMismatch());
                continue;
            }
            reason = format.streamFault(buf, p);
            if (reason != null) {
                drop(reason);
                continue;
            }
            int total = header + FrameFormat.size(buf, p);
            if (count < total) {
                return;
            }
            reason = format.check(buf, p, total);
            if (reason != null) {
                drop(reason);
                continue;
            }
            F frame = format.frameAt(buf, p);
            start += total;
            count -= total;
            reportRun();
            frames.accept(frame);
        }
    }

    private void drop(R reason) {
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
            R r = skipReason;
            skipped = 0;
            skipReason = null;
            rejections.accept(r, n);
        }
    }
}
