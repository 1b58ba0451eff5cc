package org.tinysep.amica.protocol;

import org.tinysep.link.frame.FrameStream;

/**
 * Finds AmICA frames in a byte stream, such as the serial link to the modified AmICA node (thesis Figure 3.12).
 * A candidate fails on its header value, on its size identifier versus its payload length, or on its checksum.
 * <p>
 * Buffering, resynchronisation after a failing candidate (exactly one byte dropped, the search restarts at the next,
 * so a valid frame right after garbage is still found), the reporting of dropped runs (once each, with the reason
 * seen at the run's first byte, in chunks of at most {@value #BUFFER_SIZE} bytes), {@code reset} and the bounded
 * buffer are the skeleton both families share, {@link FrameStream} (libs/org.tinysep.link, compiled into this
 * bundle); this class adds the rules of {@code AmicaFormat}. Not thread-safe: one reader thread feeds one decoder; sink
 * callbacks run inside {@code accept} and must not call back into it.
 */
public final class AmicaStreamDecoder extends FrameStream<AmicaFrame, RejectReason> {

    /** Receives what the decoder finds: valid frames in stream order, and each run of dropped bytes. */
    public interface Sink extends FrameStream.Sink<AmicaFrame, RejectReason> {
    }

    /** @param sink receives frames and rejections */
    public AmicaStreamDecoder(Sink sink) {
        super(AmicaFormat.INSTANCE, sink);
    }
}
