package org.tinysep.amica.busradio.udp.internal;

import java.net.InetSocketAddress;
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

/**
 * Turns one datagram into a delivery to a bus device, a new bus device (keep-alive from an unknown node), or a
 * counted rejection. Runs on the receive thread only.
 */
final class FrameHandler implements UdpTransport.Receiver {

    /** Where nodes live: the driver's node table. */
    interface Nodes {
        AmicaBusDevice find(AmicaAddress address);

        AmicaBusDevice create(AmicaAddress address, KeepAlive keepAlive, InetSocketAddress from, Instant at);
    }

    private final DriverContext context;
    private final Nodes nodes;
    private final RejectCounter rejects;
    private final AtomicLong received = new AtomicLong();

    FrameHandler(DriverContext context, Nodes nodes, RejectCounter rejects) {
        this.context = context;
        this.nodes = nodes;
        this.rejects = rejects;
    }

    @Override
    public void datagram(byte[] data, int length, InetSocketAddress from) {
        received.incrementAndGet();
        Instant at = context.now();
        byte[] raw = Arrays.copyOf(data, length);
        String origin = from.getAddress().getHostAddress() + ":" + from.getPort();
        AmicaFrame frame;
        AmicaPayload payload;
        try {
            frame = AmicaCodec.decode(data, 0, length);
            payload = AmicaPayloads.decode(frame.payload());
        } catch (AmicaProtocolException e) {
            reject(e.reason(), e.getMessage(), raw, origin);
            return;
        }
        AmicaBusDevice device = nodes.find(frame.sender());
        if (device == null) {
            if (!(payload instanceof KeepAlive keepAlive)) {
                reject(RejectReason.UNKNOWN_NODE, new AmicaProtocolException(RejectReason.UNKNOWN_NODE, "node "
                        + frame.sender() + " sent " + payload.getClass().getSimpleName() + " before any keep-alive")
                        .getMessage(), raw, origin);
                return;
            }
            context.reporter().packet(Direction.RECEIVED, "node " + frame.sender() + " via " + origin, raw, "");
            device = nodes.create(frame.sender(), keepAlive, from, at);
        } else {
            context.reporter().packet(Direction.RECEIVED, "node " + frame.sender() + " via " + origin, raw, "");
        }
        device.received(frame, payload, from, at);
    }

    private void reject(RejectReason reason, String message, byte[] raw, String origin) {
        rejects.reject(reason, message, origin);
        context.reporter().packet(Direction.RECEIVED, origin, raw, message);
    }

    long received() {
        return received.get();
    }
}
