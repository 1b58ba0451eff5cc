package org.tinysep.sunspot.protocol;

import java.util.Objects;
import org.tinysep.link.frame.FrameStream;

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
 * The skeleton is shared with the other protocol family ({@code org.tinysep.link.frame.FrameStream}); this
 * class adds the frame rules of {@code SunSpotFormat}.
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
    public static final int BUFFER_SIZE = FrameStream.BUFFER_SIZE;

    private final FrameStream<SunSpotFrame, RejectReason> stream;

    /** @param sink receives frames and rejections */
    public SunSpotStreamDecoder(Sink sink) {
        this.stream = new FrameStream<>(SunSpotFormat.INSTANCE, Objects.requireNonNull(sink, "sink")::frame,
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
     * only an incomplete candidate was buffered). No run is longer than {@value #BUFFER_SIZE}: if the two together
     * exceed it, the first {@value #BUFFER_SIZE} bytes are reported with the run's reason and the rest of the
     * candidate as a second, {@link RejectReason#TRUNCATED} run.
     */
    public void reset() {
        stream.reset();
    }

    /** @return how many bytes are buffered, waiting to complete a candidate frame; at most {@value #BUFFER_SIZE} */
    public int buffered() {
        return stream.buffered();
    }
}
