package org.tinysep.amica.busradio.base;

import java.time.Instant;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.RejectSampler;

/**
 * Turns one frame into a delivery to a bus device, a new bus device (keep-alive from an unknown node), or a
 * counted rejection; every input ends up in the packet log, a rejected one with its reason. Runs on the
 * transport's receive thread only.
 *
 * @param <R> the route type (where a frame came from)
 */
public final class FrameHandler<R> {

    /** Where nodes live: the driver's node table. */
    public interface Nodes<R> {
        AmicaBusDevice<R> find(AmicaAddress address);

        /** @return the new bus device, or null when the node may not be created (over the node cap) */
        AmicaBusDevice<R> create(AmicaAddress address, KeepAlive keepAlive, R from, Instant at);

        /** @return the route for logs, e.g. {@code 127.0.0.1:5000} */
        String describe(R route);
    }

    private final DriverContext context;
    private final Nodes<R> nodes;
    private final RejectCounter rejects;
    private final RejectSampler sampler;
    private final AtomicLong received = new AtomicLong();
    private volatile Instant lastStamp;

    public FrameHandler(DriverContext context, Nodes<R> nodes, RejectCounter rejects) {
        this.context = context;
        this.nodes = nodes;
        this.rejects = rejects;
        this.sampler = new RejectSampler(context.reporter(), context.driverUid());
    }

    /** Handles bytes that must be exactly one frame, such as a UDP datagram; {@code data} may be reused after. */
    public void datagram(byte[] data, int length, R from) {
        datagram(data, length, from, null);
    }

    /**
     * Like {@link #datagram(byte[], int, Object)}, stamped {@code at} instead of the platform time now: a
     * transport that takes a late frame during a platform tick stamps it with the time it arrived in (the time
     * before the tick), as it would have been stamped on time. Never earlier than the last stamp given.
     *
     * @param at the platform time of the frame; {@code null} for now
     */
    public void datagram(byte[] data, int length, R from, Instant at) {
        received.incrementAndGet();
        byte[] raw = Arrays.copyOf(data, length);
        AmicaFrame frame;
        try {
            frame = AmicaCodec.decode(data, 0, length);
        } catch (AmicaProtocolException e) {
            reject(e.reason(), e.getMessage(), raw, from);
            return;
        }
        handle(frame, raw, from, at);
    }

    /** Handles a frame already found in a byte stream (framing checked); {@code raw} are its bytes. */
    public void frame(AmicaFrame frame, byte[] raw, R from) {
        received.incrementAndGet();
        handle(frame, raw, from, null);
    }

    /**
     * Records input that the transport's framing already rejected, e.g. a run of bytes a stream decoder skipped:
     * counted under its reason and written to the packet log.
     */
    public void rejected(RejectReason reason, String message, byte[] raw, R from) {
        reject(reason, message, raw, from);
    }

    private void handle(AmicaFrame frame, byte[] raw, R from, Instant stamp) {
        Instant last = lastStamp;
        Instant at = stamp == null ? context.now() : last != null && stamp.isBefore(last) ? last : stamp;
        lastStamp = at;
        String origin = nodes.describe(from);
        AmicaPayload payload;
        try {
            payload = AmicaPayloads.decode(frame.payload());
        } catch (AmicaProtocolException e) {
            reject(e.reason(), e.getMessage(), raw, from);
            return;
        }
        AmicaBusDevice<R> device = nodes.find(frame.sender());
        if (device == null) {
            if (!(payload instanceof KeepAlive keepAlive)) {
                reject(RejectReason.UNKNOWN_NODE, new AmicaProtocolException(RejectReason.UNKNOWN_NODE, "node "
                        + frame.sender() + " sent " + payload.getClass().getSimpleName() + " before any keep-alive")
                        .getMessage(), raw, from);
                return;
            }
            device = nodes.create(frame.sender(), keepAlive, from, at);
            if (device == null) { // over the bus radio's node cap: counted by the node table
                sampler.rejected(origin, raw, "rejected: node " + frame.sender() + " would exceed maxNodes");
                return;
            }
            context.reporter().packet(Direction.RECEIVED, "node " + frame.sender() + " via " + origin, raw, "");
        } else {
            context.reporter().packet(Direction.RECEIVED, "node " + frame.sender() + " via " + origin, raw, "");
        }
        device.received(frame, payload, from, at);
    }

    private void reject(RejectReason reason, String message, byte[] raw, R from) {
        String origin = nodes.describe(from);
        rejects.reject(reason, message, origin);
        sampler.rejected(origin, raw, message);
    }

    /**
     * Records a datagram the transport refused for its source (not on the allow-list, over the rate limit; the
     * transport's {@code SourceGate} counts it): in the packet log, sampled like every rejected input.
     */
    public void refused(String why, byte[] data, int length, R from) {
        received.incrementAndGet();
        sampler.rejected(nodes.describe(from), Arrays.copyOf(data, length), why);
    }

    /** Writes the summary of rejected frames not kept in the packet log, at most once a minute; call on a tick. */
    public void flushRejects() {
        sampler.flush();
    }

    /** @return how many datagrams or frames were handed in (rejected ones included, stream runs not) */
    public long received() {
        return received.get();
    }
}
