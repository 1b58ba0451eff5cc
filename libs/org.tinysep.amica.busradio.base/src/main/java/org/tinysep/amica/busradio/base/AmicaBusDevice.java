package org.tinysep.amica.busradio.base;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.device.support.health.HealthWords;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.health.NodeWatch;
import org.tinysep.device.support.health.ReportRates;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Uids;

/**
 * One AmICA sensor node as seen through a bus radio (thesis 4.4.1). Forwards every valid payload to its listeners
 * without analysing it, and sends commands back along the route the node was last heard on.
 *
 * @param <R> the route type: where the node was last heard and where its commands go
 */
public final class AmicaBusDevice<R> extends AbstractDevice implements BusRadioAmicaProvider, NodeHealthSource {

    /** How often an AmICA node sends its keep-alive (the thesis gives no rate; the simulator's, a TinySEP choice). */
    public static final Duration KEEP_ALIVE_PERIOD = Duration.ofSeconds(60);

    /** The driver's side, its node table: sends a command payload to the node along a route. */
    public interface Link<R> {
        /** Frames and queues the payload; never blocks. */
        void send(AmicaBusDevice<R> device, byte[] payload, R route);

        /** @return the route for the user, e.g. {@code 127.0.0.1:5000} or {@code /dev/ttyUSB0} */
        String describe(R route);

        /** Forgets a bus device its driver removed (it calls this as it is disposed), so the node comes anew. */
        void forget(AbstractDevice device);

        /** The device's next health check came closer than planned (e.g. it was heard after a silence). */
        default void healthDueEarlier() {
        }
    }

    private static final Logger LOG = LoggerFactory.getLogger(AmicaBusDevice.class);

    private final AmicaAddress address;
    private final Link<R> link;
    /** The listeners, the handover for replacements, and the way payloads reach them */
    private final BusLanes listeners;
    private final AtomicLong packets = new AtomicLong();
    private volatile Set<String> nodeTypes;
    private volatile KeepAlive keepAlive;
    private volatile R route;
    private volatile Instant lastSeen;
    private volatile NodePolicy policy = NodePolicy.DEFAULT;
    private final NodeWatch watch;
    private final BatteryWatch battery = new BatteryWatch();
    private final NodeTypeGuard guard = new NodeTypeGuard();

    /**
     * @param type  the device type, e.g. {@code BusRadioAmicaUdp}; the UID derives from the driver name and the
     *              node address
     * @param route where the keep-alive came from
     */
    public AmicaBusDevice(DriverContext context, String type, AmicaAddress address, KeepAlive keepAlive, R route,
            Link<R> link) {
        super(context, Uids.of(context.driverName(), address.toString()), type, "AmICA node " + address);
        this.address = address;
        this.link = link;
        this.route = route;
        this.keepAlive = keepAlive;
        this.listeners = new BusLanes(this, "AmICA node " + address);
        this.nodeTypes = typeNames(keepAlive);
        serviceProperty(DeviceProperties.NODE_ADDRESS, address.toString());
        serviceProperty(DeviceProperties.NODE_TYPE, nodeTypes.toArray(String[]::new));
        this.watch = new NodeWatch(interval(nodeTypes), perSecond(nodeTypes), null);
        watch.onDueEarlier(link == null ? () -> { } : link::healthDueEarlier);
        publish(this, BusRadioAmicaProvider.class, NodeHealthSource.class);
    }

    private static Duration interval(Set<String> types) {
        return ReportRates.interval(types, KEEP_ALIVE_PERIOD);
    }

    private static double perSecond(Set<String> types) {
        return ReportRates.perSecond(types) + 1.0 / KEEP_ALIVE_PERIOD.getSeconds();
    }

    /** Sets the health settings (silence, low battery); the node table passes its bus radio's. */
    public void policy(NodePolicy policy) {
        this.policy = policy;
        if (link != null) {
            link.healthDueEarlier();
        }
    }

    /** @return epoch millis of this node's next health check that can say something (see {@link #checkHealth}) */
    long healthDueMillis() {
        return watch.dueMillis();
    }

    /** Sets the real time a node must also be silent for (see {@code NodeWatch.realSilenceGuard}). */
    public void realSilenceGuard(Duration guard) {
        watch.realSilenceGuard(guard);
    }

    /**
     * Re-creates the bus device of a node known before the restart (docs/backup.md): its last keep-alive and last
     * seen time come from the backup, it has no route until the node is heard again, and its status says so.
     *
     * @throws IllegalArgumentException when the backup lacks the node address or keep-alive
     */
    public static <R> AmicaBusDevice<R> restored(DriverContext context, String type, ComponentBackup saved,
            Link<R> link) {
        Map<String, String> s = saved.state();
        KeepAlive ka = new KeepAlive(Long.parseLong(s.getOrDefault("uptimeSeconds", "0")),
                Integer.parseInt(s.getOrDefault("batteryMillivolts", "0")), Integer.parseInt(s.get("vendorId")),
                Integer.parseInt(s.get("productId")), Long.parseLong(s.getOrDefault("serialNumber", "0")));
        AmicaBusDevice<R> d = new AmicaBusDevice<>(context, type, AmicaAddress.parse(saved.nodeAddress()), ka,
                null, link);
        d.lastSeen = saved.lastSeen();
        d.watch.restored(saved.lastSeen());
        d.offline(NOT_HEARD + (saved.lastSeen() == null ? "" : " (last seen " + saved.lastSeen() + ")"));
        return d;
    }

    /** The status detail of a node re-created from the backup and not heard since. */
    public static final String NOT_HEARD = "not heard since restart";

    @Override
    protected Instant lastSeen() {
        return lastSeen;
    }

    @Override
    protected Map<String, String> backupState() {
        KeepAlive ka = keepAlive;
        Map<String, String> m = new LinkedHashMap<>();
        m.put("vendorId", Integer.toString(ka.vendorId()));
        m.put("productId", Integer.toString(ka.productId()));
        m.put("serialNumber", Long.toString(ka.serialNumber()));
        m.put("batteryMillivolts", Integer.toString(ka.batteryMillivolts()));
        m.put("uptimeSeconds", Long.toString(ka.uptimeSeconds()));
        return m;
    }

    private static Set<String> typeNames(KeepAlive keepAlive) {
        Set<String> names = new TreeSet<>();
        keepAlive.nodeTypes().forEach(t -> names.add(t.typeName()));
        return Set.copyOf(names);
    }

    /** Handles one valid frame from this node, on the receive thread: the device is ONLINE again. */
    public void received(AmicaFrame frame, AmicaPayload payload, R from, Instant at) {
        packets.incrementAndGet();
        route = from;
        lastSeen = at;
        Instant silence = watch.heard(at, frame.sequence());
        if (payload instanceof KeepAlive ka) {
            keepAlive(ka, from);
        }
        if (silence != null) {
            event(HealthWords.heardAgain(silence, at));
        }
        status(DeviceStatus.State.ONLINE, "");
        listeners.received(frame.payload(), at); // queued in order for the radio's dispatcher, if it has one
        stateChanged(); // last seen, saved at most every 10 s, never on this thread
    }

    /**
     * A keep-alive: the same types, or other types while no device depends on the node, are taken as they are;
     * other types while devices depend on it are held, counted and reported ({@link NodeTypeGuard}).
     * The frame still counts as heard and is still forwarded (abstraction devices ignore keep-alives).
     */
    private void keepAlive(KeepAlive ka, R from) {
        Set<String> types = typeNames(ka);
        if (types.equals(nodeTypes)) {
            keepAlive = ka;
            guard.agreed();
        } else if (dependedOn()) {
            NodeTypeGuard.Claim claim = new NodeTypeGuard.Claim(types, ka, link.describe(from));
            if (guard.mismatch(claim)) {
                String problem = NodeTypeGuard.problem("AmICA node " + address, nodeTypes, claim,
                        NodeTypeGuard.dependents(listeners.connected()), uid(),
                        guard.reportsExhausted());
                LOG.warn("{}", problem);
                context.reporter().event(EventKind.PROBLEM, uid(), problem);
            }
            return; // neither the types nor the rest of this keep-alive (battery, serial number) are taken
        } else {
            retype(ka, "node types changed from " + nodeTypes + " to " + types);
        }
        batteryReport(ka.batteryMillivolts());
    }

    /** @return whether devices depend on the node: listeners connected, or one left and its replacement is due */
    private boolean dependedOn() {
        return listeners.dependedOn();
    }

    /**
     * Payloads reach the listeners through the radio's ordered dispatcher (a slow listener never stalls
     * the radio); without one (null) on the receive thread.
     */
    public void delivery(OrderedDelivery delivery) {
        listeners.delivery(delivery);
    }

    /** Takes the keep-alive's types as the node's, with an event entry; its devices follow the service property. */
    private synchronized void retype(KeepAlive ka, String entry) {
        Set<String> types = typeNames(ka);
        keepAlive = ka;
        event(entry);
        nodeTypes = types;
        watch.rates(interval(types), perSecond(types));
        serviceProperty(DeviceProperties.NODE_TYPE, types.toArray(String[]::new));
    }

    @Override
    public List<DeviceFunction> functions() {
        return List.of(new DeviceFunction(NodeTypeGuard.ACCEPT, "applies the node types a keep-alive claimed"
                + " (pendingNodeTypes): only after a real change of the node; its devices change with them"));
    }

    /** {@value NodeTypeGuard#ACCEPT}: the installer confirms that the node really changed its types. */
    @Override
    public String invoke(String function) {
        if (!NodeTypeGuard.ACCEPT.equals(function)) {
            return super.invoke(function);
        }
        NodeTypeGuard.Claim claim = guard.take();
        if (claim == null) {
            throw new IllegalArgumentException("no node types are pending: the node's last keep-alive agreed with"
                    + " its types " + nodeTypes);
        }
        Set<String> before = nodeTypes;
        retype(claim.keepAlive(), "node types changed from " + before + " to " + claim.types() + ": confirmed by"
                + " the installer (" + NodeTypeGuard.ACCEPT + "; claimed by a keep-alive from " + claim.from() + ")");
        return "node types now " + claim.types() + " (were " + before + "); the devices of the old types go, those of"
                + " the new ones come";
    }

    private void batteryReport(int millivolts) {
        switch (battery.update(millivolts, policy.lowBatteryMillivolts())) {
            case LOW -> context.reporter().event(EventKind.PROBLEM, uid(), HealthWords.lowBattery("AmICA node "
                    + address + " (" + name() + ")", millivolts, policy.lowBatteryMillivolts()));
            case RECOVERED -> event("battery fine again: " + millivolts + " mV");
            default -> { }
        }
    }

    /**
     * Checks for silence on a platform tick: a node not heard for the policy's number of report intervals goes
     * OFFLINE with a PROBLEM entry in plain words; its next valid frame brings it back ONLINE. Returns at once, with no
     * allocation, while nothing can be due ({@link NodeWatch#due}).
     */
    public void checkHealth(Instant now) {
        NodePolicy p = policy;
        if (!watch.due(now, p.silentAfterIntervals())) {
            return; // heard within its limit, or silent and not flapping: nothing to say this tick
        }
        String node = "AmICA node " + address + " (" + name() + ")";
        if (watch.checkSilence(now, p.silentAfterIntervals())) {
            Instant since = watch.silentSince();
            context.reporter().event(EventKind.PROBLEM, uid(), HealthWords.silentProblem(node, since, now,
                    watch.interval(), watch.missedIntervals(p.silentAfterIntervals(), now)));
            status(DeviceStatus.State.OFFLINE, HealthWords.silentDetail(since, watch.interval()));
        }
        String flapping = watch.flapping(node, now); // damped: one notice, then at most one line an hour
        if (flapping != null) {
            context.reporter().event(flapping.startsWith("Monitoring reduced: ") ? EventKind.PROBLEM
                    : EventKind.DEVICE_EVENT, uid(), flapping);
        }
    }

    @Override
    public int healthFlags() {
        boolean online = !watch.silent() && status().state() == DeviceStatus.State.ONLINE;
        return (online ? 1 : 0) | (battery.low() ? 2 : 0);
    }

    @Override
    public NodeHealth health() {
        Instant now = now();
        int mv = keepAlive.batteryMillivolts();
        return new NodeHealth(uid(), address.toString(), nodeTypes,
                !watch.silent() && status().state() == DeviceStatus.State.ONLINE, watch.lastHeard(),
                watch.silentSince(), watch.interval(), mv == 0 ? null : mv, battery.low(), watch.received(now),
                watch.expected(now), watch.sequenceGaps());
    }

    /** Marks the device OFFLINE, e.g. because its link went down; the next packet brings it back ONLINE. */
    public void offline(String detail) {
        status(DeviceStatus.State.OFFLINE, detail);
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    /**
     * Connects a listener. One that replaces a listener which left in the last 10 s (its driver is being updated)
     * first gets the payloads received since, in order ({@link Handover}); nothing is lost in the swap.
     */
    @Override
    public Connection connect(BusRadioAmicaListener listener) {
        if (listener == null) {
            throw new IllegalArgumentException("listener must not be null");
        }
        return listeners.connect(listener);
    }

    @Override
    public String nodeId() {
        return address.toString();
    }

    @Override
    public Set<String> nodeTypes() {
        return nodeTypes;
    }

    @Override
    public void send(byte[] payload) {
        if (payload == null || payload.length == 0 || payload.length > AmicaCodec.MAX_PAYLOAD) {
            throw new IllegalArgumentException("AmICA payload must be 1.." + AmicaCodec.MAX_PAYLOAD + " bytes, was "
                    + (payload == null ? "null" : payload.length));
        }
        link.send(this, payload.clone(), route);
    }

    public AmicaAddress address() {
        return address;
    }

    /** @return keep-alives whose node types disagreed while devices depended on the node (not applied) */
    public long typeMismatches() {
        return guard.mismatches();
    }

    /** @return where the node was last heard */
    public R route() {
        return route;
    }

    @Override
    protected List<Parameter> moreParameters() {
        KeepAlive ka = keepAlive;
        List<Parameter> out = new ArrayList<>(List.of(
                Parameter.readOnly("node", address, "netgroup.address of the node"),
                Parameter.readOnly("nodeTypes", String.join(",", nodeTypes), "from the keep-alive product id"),
                Parameter.readOnly("remote", route == null ? NOT_HEARD : link.describe(route),
                        "where the node was last heard from; commands go there"),
                Parameter.readOnly("lastSeen", lastSeen, "time of the last valid packet"),
                Parameter.readOnly("packets", packets.get(), "valid packets received"),
                Parameter.readOnly("uptimeSeconds", ka.uptimeSeconds(), "from the last keep-alive"),
                Parameter.readOnly("batteryMillivolts", ka.batteryMillivolts(), "from the last keep-alive"),
                Parameter.readOnly("battery", battery.describe(ka.batteryMillivolts(), policy.lowBatteryMillivolts()),
                        "battery state from the last keep-alive"),
                Parameter.readOnly("reportInterval", HealthWords.span(watch.interval()),
                        "how often the node's types promise a report (thesis 3.9)"),
                Parameter.readOnly("linkQuality", watch.describeQuality(now()),
                        "reports received vs promised (thesis Table 5.4)"),
                Parameter.readOnly("sequenceGaps", watch.sequenceGaps(), "frames missing by sequence number"),
                Parameter.readOnly("vendorId", ka.vendorId(), "from the last keep-alive"),
                Parameter.readOnly("productId", ka.productId(), "node type bitmask, see docs/protocols/amica.md"),
                Parameter.readOnly("serialNumber", ka.serialNumber(), "from the last keep-alive")));
        out.addAll(guard.parameters());
        return out;
    }

    /** Closes the connections and leaves the node table (its driver removed it). */
    @Override
    protected void onDispose() {
        listeners.closeAll();
        link.forget(this);
    }
}
