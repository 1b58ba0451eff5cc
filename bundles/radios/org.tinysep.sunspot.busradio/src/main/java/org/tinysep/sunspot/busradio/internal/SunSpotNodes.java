package org.tinysep.sunspot.busradio.internal;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.UnaryOperator;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.Backups;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * The node table shared by every link: one bus device per Sun SPOT address, created (and registered through the
 * driver) on the first valid packet from an address, forgotten when the driver removed it. Creation is serialised,
 * so two links hearing a new node at once still create one device. Thread-safe.
 */
final class SunSpotNodes {

    private final Map<SunSpotAddress, SunSpotBusDevice> nodes = new ConcurrentHashMap<>();
    private final Object creating = new Object();
    private final DriverContext context;
    private final String deviceType;
    private final UnaryOperator<SunSpotBusDevice> register;
    private final AtomicLong overCap = new AtomicLong();
    private volatile NodePolicy policy = NodePolicy.DEFAULT;
    private volatile OrderedDelivery delivery;

    /**
     * @param deviceType the type of the bus devices, {@code BusRadioSunSpot}
     * @param register   registers a new bus device with the driver ({@code AbstractDriver.addDevice}); tests
     *                   without a framework pass the identity
     */
    SunSpotNodes(DriverContext context, String deviceType, UnaryOperator<SunSpotBusDevice> register) {
        this.context = context;
        this.deviceType = deviceType;
        this.register = register;
    }

    /** The radio's ordered delivery for every bus device's listeners (null: on the receive thread, in tests). */
    void delivery(OrderedDelivery d) {
        this.delivery = d;
    }

    OrderedDelivery delivery() {
        return delivery;
    }

    /** Sets the health and capacity settings (silence, maxNodes; Sun SPOTs report no battery). */
    void policy(NodePolicy policy) {
        this.policy = policy;
    }

    /**
     * @return the bus device of {@code address}, created and registered now if it is new; null when it is new and
     *         the bus radio has {@code maxNodes} already (2,000 frames from random addresses made 2,000
     *         devices): counted, the first one a PROBLEM
     */
    SunSpotBusDevice findOrCreate(SunSpotAddress address, SunSpotSensorType type, String link) {
        SunSpotBusDevice known = nodes.get(address);
        if (known != null) {
            return known;
        }
        synchronized (creating) {
            known = nodes.get(address);
            if (known != null) {
                return known;
            }
            NodePolicy p = policy;
            if (nodes.size() >= p.maxNodes()) {
                if (overCap.incrementAndGet() == 1) {
                    context.event(EventKind.PROBLEM, "Sun SPOT " + address + " (via " + link + ") not created: this "
                            + "bus radio already has " + nodes.size() + " nodes, its limit (maxNodes = " + p.maxNodes()
                            + "). Further new addresses are rejected and only counted (rejected.node_cap).");
                }
                return null;
            }
            SunSpotBusDevice device = new SunSpotBusDevice(context, deviceType, address, type, link, this);
            nodes.put(address, device);
            try {
                return register.apply(device);
            } catch (RuntimeException e) { // e.g. the bundle is stopping: the next packet tries again
                nodes.remove(address, device);
                throw e;
            }
        }
    }

    /** Re-creates the bus devices of the nodes known before the restart; an unusable backup is reported. */
    int restore(List<ComponentBackup> saved) {
        return Backups.recreate(context, saved, b -> SunSpotBusDevice.restored(context, deviceType, b, this), d -> {
            synchronized (creating) {
                return nodes.putIfAbsent(d.address(), d) == null;
            }
        }, register);
    }

    /** Checks every node for silence (sensor health); call on each platform tick. */
    void checkHealth(Instant now) {
        int missed = policy.silentAfterIntervals();
        nodes.values().forEach(d -> d.checkHealth(now, missed));
    }

    long overCap() {
        return overCap.get();
    }

    /** @return {@code maxNodes}, {@code rejected.node_cap}, {@code silentAfterIntervals} */
    List<Parameter> parameters() {
        NodePolicy p = policy;
        return List.of(Parameter.readOnly("maxNodes", p.maxNodes(), "most Sun SPOTs this bus radio creates"),
                Parameter.readOnly("rejected.node_cap", overCap.get(), "packets from new addresses beyond maxNodes"),
                Parameter.readOnly("silentAfterIntervals", p.silentAfterIntervals(),
                        "missed report intervals that make a node OFFLINE"));
    }

    SunSpotBusDevice find(SunSpotAddress address) {
        return nodes.get(address);
    }

    /** Forgets a removed bus device (it calls this as it is disposed), so the node's next packet creates it anew. */
    void forget(AbstractDevice device) {
        if (device instanceof SunSpotBusDevice bus) {
            nodes.remove(bus.address(), bus);
        }
    }

    /** Marks every bus device last heard on {@code link} OFFLINE; each comes back ONLINE with its next packet. */
    void offline(String link, String detail) {
        nodes.values().forEach(d -> d.offline(link, detail));
    }

    /** @return the bus devices, in no particular order */
    List<SunSpotBusDevice> all() {
        return List.copyOf(nodes.values());
    }

    int size() {
        return nodes.size();
    }
}
