package org.tinysep.amica.busradio.base;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.UnaryOperator;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.Backups;
import org.tinysep.device.support.DriverContext;

/**
 * The node table of a bus radio and the way out to the nodes: creates a bus device per node (registered through
 * the driver), forgets it when the driver removed it, and frames commands (source = platform, destination = the
 * node, a per-driver sequence number) for the transport. Thread-safe.
 *
 * @param <R> the route type
 */
public final class AmicaNodes<R> implements FrameHandler.Nodes<R>, AmicaBusDevice.Link<R> {

    /** The driver's transport: sends frames along a route and names routes. */
    public interface Transport<R> {
        /**
         * Queues a frame; never blocks the caller.
         *
         * @param outcome told once, on any thread: null when sent, otherwise the note for the packet log
         */
        void transmit(byte[] frame, R route, Outcome outcome);

        /** @return the route for the user, e.g. {@code 127.0.0.1:5000} or {@code /dev/ttyUSB0} */
        String describe(R route);
    }

    /** The outcome of one transmission. */
    public interface Outcome {
        /** @param failure null when the frame was sent, otherwise why not (e.g. "send failed: ...") */
        void done(String failure);
    }

    private final Map<AmicaAddress, AmicaBusDevice<R>> nodes = new ConcurrentHashMap<>();
    private final AtomicInteger sequence = new AtomicInteger();
    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong failed = new AtomicLong();
    private final DriverContext context;
    private final String deviceType;
    private final Transport<R> transport;
    private final UnaryOperator<AmicaBusDevice<R>> register;

    /**
     * @param deviceType the type of the bus devices, e.g. {@code BusRadioAmicaUdp}
     * @param register   registers a new bus device with the driver ({@code AbstractDriver.addDevice}); tests
     *                   without a framework pass the identity
     */
    public AmicaNodes(DriverContext context, String deviceType, Transport<R> transport,
            UnaryOperator<AmicaBusDevice<R>> register) {
        this.context = context;
        this.deviceType = deviceType;
        this.transport = transport;
        this.register = register;
    }

    @Override
    public AmicaBusDevice<R> find(AmicaAddress address) {
        return nodes.get(address);
    }

    @Override
    public AmicaBusDevice<R> create(AmicaAddress address, KeepAlive keepAlive, R from, Instant at) {
        AmicaBusDevice<R> device = new AmicaBusDevice<>(context, deviceType, address, keepAlive, from, this);
        nodes.put(address, device);
        return register.apply(device);
    }

    /**
     * Re-creates the bus devices of the nodes known before the restart (their backups), before the transport
     * opens; a backup that cannot be used is reported and skipped.
     *
     * @return how many were re-created
     */
    public int restore(List<ComponentBackup> saved) {
        return Backups.recreate(context, saved, b -> AmicaBusDevice.restored(context, deviceType, b, this),
                d -> nodes.putIfAbsent(d.address(), d) == null, register);
    }

    /** Forgets the node of a removed bus device, so its next keep-alive creates it anew. */
    public void forget(AbstractDevice device) {
        if (device instanceof AmicaBusDevice<?> bus) {
            nodes.remove(bus.address(), bus);
        }
    }

    /** Marks every bus device OFFLINE (the link is down); each comes back ONLINE with its next packet. */
    public void offline(String detail) {
        nodes.values().forEach(d -> d.offline(detail));
    }

    /** @return the bus devices, in no particular order */
    public List<AmicaBusDevice<R>> all() {
        return List.copyOf(nodes.values());
    }

    public int size() {
        return nodes.size();
    }

    /** @return frames sent to nodes */
    public long sent() {
        return sent.get();
    }

    /** @return frames that could not be sent */
    public long failed() {
        return failed.get();
    }

    @Override
    public void send(AmicaBusDevice<R> device, byte[] payload, R route) {
        AmicaAddress node = device.address();
        if (route == null) {
            failed.incrementAndGet();
            context.reporter().packet(Direction.SENT, "node " + node, payload, "not sent: node "
                    + AmicaBusDevice.NOT_HEARD);
            return;
        }
        byte[] frame = AmicaCodec.encode(AmicaFrame.fromPlatform(node, sequence.getAndIncrement() & 0xFF, payload));
        String where = "node " + node + " via " + transport.describe(route);
        transport.transmit(frame, route, failure -> {
            if (failure == null) {
                sent.incrementAndGet();
                context.reporter().packet(Direction.SENT, where, frame, "");
            } else {
                failed.incrementAndGet();
                context.reporter().packet(Direction.SENT, where, frame, failure);
            }
        });
    }

    @Override
    public String describe(R route) {
        return route == null ? AmicaBusDevice.NOT_HEARD : transport.describe(route);
    }
}
