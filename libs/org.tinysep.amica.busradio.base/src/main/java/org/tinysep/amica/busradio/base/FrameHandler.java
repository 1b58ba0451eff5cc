package org.tinysep.amica.busradio.base;

import java.time.Instant;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.intake.PacketIntake;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * Turns one frame into a delivery to a bus device, a new bus device (keep-alive from an unknown node), or a
 * counted rejection; every input ends up in the packet log, a rejected one with its reason. Counting, copying and
 * decoding a datagram, refused sources and the sampled packet log are the shared {@link PacketIntake}'s. Runs on
 * the transport's receive thread only.
 *
 * @param <R> the route type (where a frame came from)
 */
public final class FrameHandler<R> extends PacketIntake<AmicaFrame, RejectReason, AmicaProtocolException, R> {

    /** Where nodes live: the driver's node table. */
    public interface Nodes<R> {
        AmicaBusDevice<R> find(AmicaAddress address);

        /** @return the new bus device, or null when the node may not be created (over the node cap) */
        AmicaBusDevice<R> create(AmicaAddress address, KeepAlive keepAlive, R from, Instant at);

        /** @return the route for logs, e.g. {@code 127.0.0.1:5000} */
        String describe(R route);
    }

    /**
     * A datagram is one frame; the reason of a bad one is its exception's ({@code e -> e.reason()}, not a method
     * reference: that would name the private package declaring {@code reason()} and make this bundle import it).
     */
    private static final Codec<AmicaFrame, RejectReason, AmicaProtocolException> CODEC = new Codec<>(
            raw -> AmicaCodec.decode(raw, 0, raw.length), AmicaProtocolException.class, e -> e.reason());

    private final Nodes<R> nodes;
    private volatile Instant lastStamp;
    /** The packet log's "node 1:17 via 127.0.0.1:5000" of received frames, formatted once per node and route. */
    private final Origins<R> origins;

    public FrameHandler(DriverContext context, Nodes<R> nodes, RejectCounter<RejectReason> rejects) {
        super(context, CODEC, rejects::reject);
        this.nodes = nodes;
        this.origins = new Origins<>(nodes::describe);
    }

    /**
     * A frame is stamped {@code stamp} (a transport's late frame during a platform tick, see
     * {@link #datagram(byte[], int, Object, Instant)}) or the platform time now; never earlier than the last stamp.
     */
    @Override
    protected void handle(AmicaFrame frame, byte[] raw, R from, Instant stamp) {
        Instant last = lastStamp;
        Instant at = stamp == null ? context().now() : last != null && stamp.isBefore(last) ? last : stamp;
        lastStamp = at;
        AmicaPayload payload;
        try {
            payload = AmicaPayloads.decode(frame.payload());
        } catch (AmicaProtocolException e) {
            reject(e.reason(), e.getMessage(), raw, from);
            return;
        }
        AmicaAddress sender = frame.sender(); // once per frame
        AmicaBusDevice<R> device = nodes.find(sender);
        if (device == null) {
            if (!(payload instanceof KeepAlive keepAlive)) {
                reject(RejectReason.UNKNOWN_NODE, new AmicaProtocolException(RejectReason.UNKNOWN_NODE, "node "
                        + sender + " sent " + payload.getClass().getSimpleName() + " before any keep-alive")
                        .getMessage(), raw, from);
                return;
            }
            device = nodes.create(sender, keepAlive, from, at);
            if (device == null) { // over the bus radio's node cap: counted by the node table
                sample(nodes.describe(from), raw, "rejected: node " + sender + " would exceed maxNodes");
                return;
            }
        }
        context().reporter().packet(Direction.RECEIVED, originOf(sender, from), raw, "");
        device.received(frame, payload, from, at);
    }

    /** @return "node 1:17 via 127.0.0.1:5000", formatted at the first frame of that node by that route */
    String originOf(AmicaAddress sender, R from) {
        return origins.of(sender, from);
    }

    @Override
    protected String origin(R from) {
        return nodes.describe(from);
    }
}
