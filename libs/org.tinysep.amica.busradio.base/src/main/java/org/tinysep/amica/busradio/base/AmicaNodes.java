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
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.Backups;
import org.tinysep.device.support.lifecycle.DriverContext;

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
    private final AtomicLong overCap = new AtomicLong();
    /** The packet log's "node 1:17 via 127.0.0.1:5000" of sent commands, formatted once per node and route. */
    private final Origins<R> origins;
    private volatile NodePolicy policy = NodePolicy.DEFAULT;
    private volatile OrderedDelivery delivery;
    private volatile java.time.Duration realSilenceGuard = java.time.Duration.ZERO;
    /** Set when a node's next health check came closer than planned: the next tick looks through the nodes. */
    private volatile boolean healthDirty = true;
    /** The platform tick's own (one thread): when the first node's check is due, the tick before, its rounds. */
    private long nextHealthCheck = Long.MIN_VALUE;
    private long lastHealthTick = Long.MIN_VALUE;
    private long healthRounds;

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
        this.origins = new Origins<>(transport::describe);
        this.register = register;
    }

    @Override
    public AmicaBusDevice<R> find(AmicaAddress address) {
        return nodes.get(address);
    }

    /**
     * For a transport whose frames are handled on its own thread, not on the platform tick (serial): a node must
     * also be silent this long in real time before it goes OFFLINE, so a receive thread lagging behind lock-step
     * ticks does not make nodes look silent. The UDP bus radio drains its socket on each tick and needs none.
     */
    public void realSilenceGuard(java.time.Duration guard) {
        this.realSilenceGuard = guard;
        nodes.values().forEach(d -> d.realSilenceGuard(guard));
    }

    /**
     * Payloads reach the bus devices' listeners through this ordered dispatcher (a slow listener never
     * stalls the radio), for the nodes known and those to come; null = on the receive thread.
     */
    public void delivery(OrderedDelivery delivery) {
        this.delivery = delivery;
        nodes.values().forEach(d -> d.delivery(delivery));
    }

    /** Sets the health and capacity settings, for the nodes known and those to come. */
    public void policy(NodePolicy policy) {
        this.policy = policy;
        nodes.values().forEach(d -> d.policy(policy));
    }

    /**
     * Creates the bus device of a new node, unless the bus radio has {@code maxNodes} already (a flood
     * of keep-alives from made-up addresses must not create devices without end): then the node is rejected and
     * counted, and the first such rejection is a PROBLEM in the event log.
     *
     * @return the new device, or null when over the cap
     */
    @Override
    public AmicaBusDevice<R> create(AmicaAddress address, KeepAlive keepAlive, R from, Instant at) {
        NodePolicy p = policy;
        if (nodes.size() >= p.maxNodes()) {
            if (overCap.incrementAndGet() == 1) {
                context.event(EventKind.PROBLEM, "node " + address + " (via " + describe(from) + ") not created: "
                        + "this bus radio already has " + nodes.size() + " nodes, its limit (maxNodes = "
                        + p.maxNodes() + "). Further new nodes are rejected and only counted (rejected.node_cap).");
            }
            return null;
        }
        AmicaBusDevice<R> device = new AmicaBusDevice<>(context, deviceType, address, keepAlive, from, this);
        device.policy(p);
        device.delivery(delivery);
        device.realSilenceGuard(realSilenceGuard);
        nodes.put(address, device);
        healthDirty = true;
        return register.apply(device);
    }

    /**
     * Checks the nodes for silence (sensor health); call on each platform tick. Looks through the nodes only when the
     * first of them is due (its silence limit ends, it flaps), when one came closer since (heard after a silence, a
     * new node, new settings) or the clock went back; an idle tick otherwise costs a comparison.
     */
    public void checkHealth(Instant now) {
        long t = now.toEpochMilli();
        boolean back = t < lastHealthTick;
        lastHealthTick = t;
        if (!healthDirty && !back && t < nextHealthCheck) {
            return;
        }
        healthDirty = false; // before the round: a node that comes closer during it marks the next tick
        healthRounds++;
        long next = Long.MAX_VALUE;
        for (AmicaBusDevice<R> d : nodes.values()) {
            d.checkHealth(now);
            next = Math.min(next, d.healthDueMillis());
        }
        nextHealthCheck = next;
    }

    /** @return the ticks on which {@link #checkHealth} looked through the nodes (for tests: work when idle) */
    public long healthRounds() {
        return healthRounds;
    }

    @Override
    public void healthDueEarlier() {
        healthDirty = true;
    }

    /** @return frames from new nodes rejected because the bus radio has {@code maxNodes} */
    public long overCap() {
        return overCap.get();
    }

    /** @return {@code maxNodes}, {@code rejected.node_cap} and the health settings, for the driver's parameters */
    public List<Parameter> parameters() {
        NodePolicy p = policy;
        return List.of(Parameter.readOnly("maxNodes", p.maxNodes(), "most nodes this bus radio creates"),
                Parameter.readOnly("rejected.node_cap", overCap.get(), "frames from new nodes beyond maxNodes"),
                Parameter.readOnly("typeMismatches", nodes.values().stream().mapToLong(AmicaBusDevice::typeMismatches)
                        .sum(), "keep-alives of known nodes whose node types disagreed, not applied"),
                Parameter.readOnly("silentAfterIntervals", p.silentAfterIntervals(),
                        "missed report intervals that make a node OFFLINE"),
                Parameter.readOnly("lowBatteryMillivolts", p.lowBatteryMillivolts(),
                        "keep-alive battery voltage reported as low"));
    }

    /**
     * Re-creates the bus devices of the nodes known before the restart (their backups), before the transport
     * opens; a backup that cannot be used is reported and skipped.
     *
     * @return how many were re-created
     */
    public int restore(List<ComponentBackup> saved) {
        return Backups.recreate(context, saved, b -> {
            AmicaBusDevice<R> d = AmicaBusDevice.restored(context, deviceType, b, this);
            d.policy(policy);
            d.delivery(delivery);
            d.realSilenceGuard(realSilenceGuard);
            return d;
        }, d -> {
            healthDirty = true;
            return nodes.putIfAbsent(d.address(), d) == null;
        }, register);
    }

    /** Forgets the node of a removed bus device, so its next keep-alive creates it anew. */
    @Override
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
        transport.transmit(frame, route, failure -> { // on the wire first, then its packet-log line (issue 29)
            String where = origins.of(node, route);
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
