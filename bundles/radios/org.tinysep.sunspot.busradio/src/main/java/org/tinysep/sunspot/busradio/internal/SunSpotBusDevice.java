package org.tinysep.sunspot.busradio.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.health.HealthWords;
import org.tinysep.device.support.health.NodeWatch;
import org.tinysep.device.support.health.ReportRates;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * One Sun SPOT as seen through the bus radio (thesis 4.4.1.3, A.2). Its node types are the sensor types seen from
 * it so far: a new one is added to the {@code tinysep.node.type} service property before the packet that revealed
 * it is delivered, so an abstraction driver that attaches because of it gets that packet too. Forwards every
 * valid payload to its listeners without analysing it, each listener getting its own copy, through the radio's
 * ordered delivery ({@link SunSpotLanes}: a slow listener never stalls a link). Thread-safe: packets may arrive on
 * several links at once.
 */
final class SunSpotBusDevice extends AbstractDevice implements BusRadioSunSpotProvider, NodeHealthSource {

    /** The report interval of a Sun SPOT of no known type (cannot happen: a device has the type it was made by). */
    private static final Duration FALLBACK_INTERVAL = Duration.ofSeconds(10);
    /**
     * Real time a Sun SPOT must also be silent for before it is OFFLINE ({@code NodeWatch.realSilenceGuard}):
     * packets are handled on each link's own thread, not on the platform tick, and in lock-step virtual time a
     * lagging receive thread must not make a node look silent.
     */
    static final Duration REAL_SILENCE_GUARD = Duration.ofSeconds(2);

    private final SunSpotAddress address;
    private final SunSpotNodes table;
    private final SunSpotLanes listeners;
    private final AtomicLong packets = new AtomicLong();
    private volatile Set<String> nodeTypes;
    private volatile String link;
    private volatile Instant lastSeen;
    private final NodeWatch watch;

    /**
     * @param type  the device type, {@code BusRadioSunSpot}; the UID derives from the driver name and the address
     * @param first the sensor type of the first packet
     * @param link  the link the first packet came on, e.g. {@code udp 127.0.0.1:5000}
     * @param table the node table, which the device leaves when its driver removes it
     */
    SunSpotBusDevice(DriverContext context, String type, SunSpotAddress address, SunSpotSensorType first,
            String link, SunSpotNodes table) {
        super(context, Uids.of(context.driverName(), address.toString()), type, "Sun SPOT " + address);
        this.address = address;
        this.link = link;
        this.table = table;
        this.listeners = new SunSpotLanes(this, "Sun SPOT " + address);
        this.nodeTypes = Set.of(first.typeName());
        serviceProperty(DeviceProperties.NODE_ADDRESS, address.toString());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {first.typeName()});
        this.watch = new NodeWatch(ReportRates.interval(nodeTypes, FALLBACK_INTERVAL),
                ReportRates.perSecond(nodeTypes), null);
        watch.realSilenceGuard(REAL_SILENCE_GUARD);
        publish(this, BusRadioSunSpotProvider.class, NodeHealthSource.class);
    }

    /** The status detail and link of a node re-created from the backup and not heard since. */
    static final String NOT_HEARD = "not heard since restart";

    /**
     * Re-creates the bus device of a node known before the restart (docs/backup.md), with its node types and last
     * seen time; it is OFFLINE until the node is heard again.
     *
     * @throws IllegalArgumentException when the backup lacks the address or a known node type
     */
    static SunSpotBusDevice restored(DriverContext context, String type, ComponentBackup saved, SunSpotNodes table) {
        List<SunSpotSensorType> types = saved.nodeTypes().stream()
                .map(t -> SunSpotSensorType.fromTypeName(t).orElseThrow(
                        () -> new IllegalArgumentException("unknown node type " + t)))
                .toList();
        if (types.isEmpty()) {
            throw new IllegalArgumentException("no node types saved");
        }
        SunSpotBusDevice d = new SunSpotBusDevice(context, type, SunSpotAddress.parse(saved.nodeAddress()),
                types.get(0), NOT_HEARD, table);
        types.forEach(d::addType);
        d.lastSeen = saved.lastSeen();
        d.watch.restored(saved.lastSeen());
        d.status(DeviceStatus.State.OFFLINE, NOT_HEARD + (saved.lastSeen() == null ? ""
                : " (last seen " + saved.lastSeen() + ")"));
        return d;
    }

    @Override
    protected Instant lastSeen() {
        return lastSeen;
    }

    /** Handles one valid packet from this node, on the link's receive thread: the device is ONLINE again. */
    void received(SunSpotFrame frame, SunSpotSensorType type, String from, Instant at) {
        link = from;
        lastSeen = at;
        addType(type);
        Instant silence = watch.heard(at, -1); // the Sun SPOT protocol has no sequence numbers
        if (silence != null) {
            event(HealthWords.heardAgain(silence, at));
        }
        status(DeviceStatus.State.ONLINE, "");
        byte[] bytes = frame.payload();
        int sensorType = frame.sensorType();
        listeners.received(table.delivery(), sensorType, bytes, at); // queued in order for the radio's dispatcher
        packets.incrementAndGet(); // counted once handed on
        stateChanged(); // last seen, saved at most every 10 s, never on this thread
    }

    private synchronized void addType(SunSpotSensorType type) {
        if (nodeTypes.contains(type.typeName())) {
            return;
        }
        Set<String> more = new TreeSet<>(nodeTypes);
        more.add(type.typeName());
        event("node type " + type.typeName() + " seen; node types now " + more);
        nodeTypes = Set.copyOf(more);
        if (watch != null) {
            watch.rates(ReportRates.interval(nodeTypes, FALLBACK_INTERVAL), ReportRates.perSecond(nodeTypes));
        }
        serviceProperty(DeviceProperties.NODE_TYPE, more.toArray(String[]::new));
    }

    /** Marks the device OFFLINE if it was last heard on {@code link}; its next packet brings it back ONLINE. */
    void offline(String lostLink, String detail) {
        if (lostLink.equals(link)) {
            status(DeviceStatus.State.OFFLINE, detail);
        }
    }

    /** Changes the real-time silence guard (tests: none). */
    void realSilenceGuard(Duration guard) {
        watch.realSilenceGuard(guard);
    }

    /** Checks for silence on a platform tick (sensor health): OFFLINE with a PROBLEM after the missed intervals. */
    void checkHealth(Instant now, int silentAfterIntervals) {
        if (!watch.due(now, silentAfterIntervals)) {
            return; // heard within its limit, or silent and not flapping: nothing to say this tick
        }
        String node = "Sun SPOT " + address + " (" + name() + ")";
        if (watch.checkSilence(now, silentAfterIntervals)) {
            Instant since = watch.silentSince();
            context.reporter().event(EventKind.PROBLEM, uid(), HealthWords.silentProblem(node, since, now,
                    watch.interval(), watch.missedIntervals(silentAfterIntervals, now)));
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
        return !watch.silent() && status().state() == DeviceStatus.State.ONLINE ? 1 : 0; // no battery reading
    }

    @Override
    public NodeHealth health() {
        Instant now = now();
        return new NodeHealth(uid(), address.toString(), nodeTypes,
                !watch.silent() && status().state() == DeviceStatus.State.ONLINE, watch.lastHeard(),
                watch.silentSince(), watch.interval(), null, false, watch.received(now), watch.expected(now), 0);
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(BusRadioSunSpotListener listener) {
        return listeners.connect(listener);
    }

    @Override
    public String nodeAddress() {
        return address.toString();
    }

    @Override
    public Set<String> nodeTypes() {
        return nodeTypes;
    }

    SunSpotAddress address() {
        return address;
    }

    /** @return the link the node was last heard on */
    String link() {
        return link;
    }

    long packets() {
        return packets.get();
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.readOnly("node", address, "64-bit IEEE address of the Sun SPOT"),
                Parameter.readOnly("nodeTypes", String.join(",", new TreeSet<>(nodeTypes)),
                        "sensor types seen from this node so far"),
                Parameter.readOnly("link", link, "where the node was last heard"),
                Parameter.readOnly("lastSeen", lastSeen, "time of the last valid packet"),
                Parameter.readOnly("packets", packets.get(), "valid packets received and delivered"),
                Parameter.readOnly("reportInterval", HealthWords.span(watch.interval()),
                        "how often the node's types promise a report (thesis 3.9.2)"),
                Parameter.readOnly("linkQuality", watch.describeQuality(now()),
                        "reports received vs promised (thesis Table 5.5)"),
                Parameter.readOnly("battery", "not reported (the Sun SPOT protocol carries no battery level)",
                        "battery state"));
    }

    /** Closes the connections and leaves the node table (its driver removed it). */
    @Override
    protected void onDispose() {
        listeners.closeAll();
        table.forget(this);
    }
}
