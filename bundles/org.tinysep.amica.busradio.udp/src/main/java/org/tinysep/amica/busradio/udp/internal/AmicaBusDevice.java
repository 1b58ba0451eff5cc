package org.tinysep.amica.busradio.udp.internal;

import java.net.InetSocketAddress;
import java.time.Instant;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;

/**
 * One AmICA sensor node as seen through the UDP bus radio (thesis 4.4.1). Forwards every valid payload to its
 * listeners without analysing it, and sends commands back to the node's last UDP source address.
 */
final class AmicaBusDevice extends AbstractDevice implements BusRadioAmicaProvider {

    /** Sends an encoded frame to the node; the driver's transport. */
    interface Link {
        void send(AmicaBusDevice device, byte[] frame, InetSocketAddress to);
    }

    private final AmicaAddress address;
    private final Link link;
    private final Listeners<BusRadioAmicaListener> listeners;
    private final AtomicLong packets = new AtomicLong();
    private volatile Set<String> nodeTypes;
    private volatile KeepAlive keepAlive;
    private volatile InetSocketAddress remote;
    private volatile Instant lastSeen;

    AmicaBusDevice(DriverContext context, AmicaAddress address, KeepAlive keepAlive, InetSocketAddress remote,
            Link link) {
        super(context, Uids.of(context.driverName(), address.toString()), context.driverName(),
                "AmICA node " + address);
        this.address = address;
        this.link = link;
        this.remote = remote;
        this.keepAlive = keepAlive;
        this.listeners = new Listeners<>(uid());
        this.nodeTypes = typeNames(keepAlive);
        serviceProperty(DeviceProperties.NODE_ADDRESS, address.toString());
        serviceProperty(DeviceProperties.NODE_TYPE, nodeTypes.toArray(String[]::new));
        publish(this, BusRadioAmicaProvider.class);
    }

    private static Set<String> typeNames(KeepAlive keepAlive) {
        Set<String> names = new TreeSet<>();
        keepAlive.nodeTypes().forEach(t -> names.add(t.typeName()));
        return Set.copyOf(names);
    }

    /** Handles one valid frame from this node, on the receive thread. */
    void received(AmicaFrame frame, AmicaPayload payload, InetSocketAddress from, Instant at) {
        packets.incrementAndGet();
        remote = from;
        lastSeen = at;
        if (payload instanceof KeepAlive ka) {
            keepAlive = ka;
            Set<String> types = typeNames(ka);
            if (!types.equals(nodeTypes)) {
                event("node types changed from " + nodeTypes + " to " + types);
                nodeTypes = types;
                serviceProperty(DeviceProperties.NODE_TYPE, types.toArray(String[]::new));
            }
        }
        status(DeviceStatus.State.ONLINE, "");
        byte[] bytes = frame.payload();
        listeners.fire(l -> l.payloadReceived(this, bytes.clone(), at));
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(BusRadioAmicaListener listener) {
        return listeners.add(listener);
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
        link.send(this, payload.clone(), remote);
    }

    AmicaAddress address() {
        return address;
    }

    @Override
    protected List<Parameter> moreParameters() {
        KeepAlive ka = keepAlive;
        return List.of(
                Parameter.readOnly("node", address, "netgroup.address of the node"),
                Parameter.readOnly("nodeTypes", String.join(",", nodeTypes), "from the keep-alive product id"),
                Parameter.readOnly("remote", remote.getAddress().getHostAddress() + ":" + remote.getPort(),
                        "UDP address the node last sent from; commands go there"),
                Parameter.readOnly("lastSeen", lastSeen, "time of the last valid packet"),
                Parameter.readOnly("packets", packets.get(), "valid packets received"),
                Parameter.readOnly("uptimeSeconds", ka.uptimeSeconds(), "from the last keep-alive"),
                Parameter.readOnly("batteryMillivolts", ka.batteryMillivolts(), "from the last keep-alive"),
                Parameter.readOnly("vendorId", ka.vendorId(), "from the last keep-alive"),
                Parameter.readOnly("productId", ka.productId(), "node type bitmask, see docs/protocols/amica.md"),
                Parameter.readOnly("serialNumber", ka.serialNumber(), "from the last keep-alive"));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
