package org.tinysep.amica.protocol;

import java.util.Objects;
import org.tinysep.link.frame.FrameStream;

/**
 * Finds AmICA frames in a byte stream, such as the serial link to the modified AmICA node (thesis Figure 3.12).
 * <p>
 * Bytes are buffered across {@link #accept(byte[], int, int)} calls. A candidate frame starts at the first buffered
 * byte: if it is complete and valid it is emitted and consumed; if its header value, its size identifier versus
 * payload length, or its checksum is wrong, exactly one byte is dropped and the search restarts at the next byte
 * (resynchronisation), so a valid frame right after garbage is still found. An incomplete candidate waits for more
 * bytes. Each run of consecutive dropped bytes is reported once, with the reason seen at its first byte, just before
 * the frame that ends it; a run that reaches {@value #BUFFER_SIZE} bytes is reported then and a new run starts, so
 * an endless stream of garbage is still reported. The buffer never holds more than {@value #BUFFER_SIZE} bytes.
 * <p>
 * The skeleton is shared with the other protocol family ({@code org.tinysep.link.frame.FrameStream}); this
 * class adds the frame rules of {@code AmicaFormat}.
 * <p>
 * Not thread-safe: one reader thread feeds one decoder. Sink callbacks run on that thread, inside
 * {@code accept}; they must not call back into this decoder. If a callback throws, the exception leaves
 * {@code accept}, the decoder stays consistent, and the bytes of that call not yet buffered are not processed.
 */
public final class AmicaStreamDecoder {

    /** Receives what the decoder finds. */
    public interface Sink {

        /** @param f a valid frame, in stream order */
        void frame(AmicaFrame f);

        /**
         * @param r            the reason seen at the first byte of the dropped run
         * @param skippedBytes how many consecutive bytes were dropped, at least 1
         */
        void rejected(RejectReason r, int skippedBytes);
    }

    /** Capacity of the buffer, in bytes; also the longest run reported in one {@link Sink#rejected} call. */
    public static final int BUFFER_SIZE = FrameStream.BUFFER_SIZE;

    private final FrameStream<AmicaFrame, RejectReason> stream;

    /** @param sink receives frames and rejections */
    public AmicaStreamDecoder(Sink sink) {
        this.stream = new FrameStream<>(AmicaFormat.INSTANCE, Objects.requireNonNull(sink, "sink")::frame,
                sink::rejected);
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
        stream.accept(src, off, len);
    }

    /**
     * Discards all buffered bytes, e.g. after the link was reopened. Bytes already dropped but not yet reported, and
     * the bytes of an incomplete candidate frame, are reported as one run (reason {@link RejectReason#TRUNCATED} if
     * only an incomplete candidate was buffered). Like every run it is reported in chunks of at most
     * {@value #BUFFER_SIZE} bytes: should it be longer, the first {@value #BUFFER_SIZE} bytes are reported with its
     * reason and the rest, bytes of the incomplete candidate, as a second run with reason
     * {@link RejectReason#TRUNCATED}.
     */
    public void reset() {
        stream.reset();
    }

    /** @return how many bytes are buffered, waiting to complete a candidate frame; at most {@value #BUFFER_SIZE} */
    public int buffered() {
        return stream.buffered();
    }
}
