package org.tinysep.amica.busradio.serial.internal;

import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.amica.busradio.base.FrameHandler;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.AmicaStreamDecoder;
import org.tinysep.amica.protocol.RejectReason;

/**
 * Bytes from a serial port → frames and skipped runs ({@link AmicaStreamDecoder}: resynchronises after garbage
 * or a bad checksum) → the shared frame logic, each with its raw bytes for the packet log. A skipped run is one
 * rejection under the reason seen at its first byte. Not thread-safe: the link's read thread is the only caller.
 *
 * @param <R> the route the bytes came from
 */
final class StreamFrames<R> implements AmicaStreamDecoder.Sink {

    private final AmicaStreamDecoder decoder = new AmicaStreamDecoder(this);
    /** Unreported skipped bytes + the decoder's buffer + one slice. */
    private final ByteQueue raw = new ByteQueue(4 * AmicaStreamDecoder.BUFFER_SIZE);
    private final AtomicLong skippedBytes = new AtomicLong();
    private final FrameHandler<R> handler;
    private final R route;

    StreamFrames(FrameHandler<R> handler, R route) {
        this.handler = handler;
        this.route = route;
    }

    /** Feeds bytes read from the port; hands on every frame and skipped run they complete. */
    void accept(byte[] buf, int len) {
        int n;
        for (int off = 0; off < len; off += n) {
            n = Math.min(len - off, AmicaStreamDecoder.BUFFER_SIZE);
            raw.append(buf, off, n);
            decoder.accept(buf, off, n);
        }
    }

    /** Forgets a partial frame, e.g. when the port was lost or reopened; what was buffered counts as skipped. */
    void reset() {
        decoder.reset();
        raw.clear();
    }

    @Override
    public void frame(AmicaFrame f) {
        handler.frame(f, raw.take(AmicaCodec.HEADER_LENGTH + f.payloadLength()), route);
    }

    @Override
    public void rejected(RejectReason reason, int skipped) {
        skippedBytes.addAndGet(skipped);
        String message = new AmicaProtocolException(reason, skipped + (skipped == 1 ? " byte" : " bytes")
                + " skipped").getMessage();
        handler.rejected(reason, message, raw.take(skipped), route);
    }

    long skippedBytes() {
        return skippedBytes.get();
    }

    /** @return bytes held, waiting to complete a frame; bounded */
    int pending() {
        return raw.size();
    }
}
