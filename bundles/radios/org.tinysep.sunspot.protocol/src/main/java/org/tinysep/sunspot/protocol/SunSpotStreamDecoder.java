package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.FrameStream;

/**
 * Finds Sun SPOT frames in a byte stream, such as the serial link to a basestation that writes framed packets.
 * Once its twelve header bytes are buffered a candidate must have S = L and a known sensor type (2..6, see
 * {@link SunSpotSensorType}); once complete it must pass the checksum and have a payload whose first byte is the
 * sensor type.
 * <p>
 * Buffering, resynchronisation after a failing candidate (exactly one byte dropped, the search restarts at the next,
 * so a valid frame right after garbage is still found), the reporting of dropped runs (once each, with the reason
 * seen at the run's first byte, in chunks of at most {@value #BUFFER_SIZE} bytes), {@code reset} and the bounded
 * buffer are the skeleton both families share, {@link FrameStream} (libs/org.tinysep.link, compiled into this
 * bundle); this class adds the rules of {@code SunSpotFormat}. Not thread-safe: one reader thread feeds one
 * decoder; sink callbacks run inside {@code accept} and must not call back into it.
 */
public final class SunSpotStreamDecoder extends FrameStream<SunSpotFrame, RejectReason> {

    /** Receives what the decoder finds: valid frames in stream order, and each run of dropped bytes. */
    public interface Sink extends FrameStream.Sink<SunSpotFrame, RejectReason> {
    }

    /** @param sink receives frames and rejections */
    public SunSpotStreamDecoder(Sink sink) {
        super(SunSpotFormat.INSTANCE, sink);
    }
}
