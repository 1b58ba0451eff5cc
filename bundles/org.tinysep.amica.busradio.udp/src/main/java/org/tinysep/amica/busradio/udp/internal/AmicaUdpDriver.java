package org.tinysep.amica.busradio.udp.internal;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.AbstractDriver;

/**
 * Bus Radio AmICA UDP/IP (thesis 4.4.1.2): listens on a UDP port, creates one {@link AmicaBusDevice} per node on
 * the node's first keep-alive, and forwards later payloads to it. Its Driver service carries the bound port
 * ({@value #PORT_PROPERTY}).
 */
@Component(service = {}, immediate = true, configurationPid = AmicaUdpDriver.PID)
@Designate(ocd = BusRadioUdpConfig.class)
public final class AmicaUdpDriver extends AbstractDriver implements FrameHandler.Nodes, AmicaBusDevice.Link {

    public static final String PID = "org.tinysep.amica.busradio.udp";
    public static final String NAME = "BusRadioAmicaUdp";
    public static final String PORT_PROPERTY = "tinysep.udp.port";

    private static final Logger LOG = LoggerFactory.getLogger(AmicaUdpDriver.class);

    private final Map<AmicaAddress, AmicaBusDevice> nodes = new ConcurrentHashMap<>();
    private final AtomicInteger sequence = new AtomicInteger();
    private final AtomicLong sent = new AtomicLong();
    private RejectCounter rejects;
    private FrameHandler handler;
    private UdpTransport transport;
    private String listening;

    public AmicaUdpDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, BusRadioUdpConfig config) {
        Map<String, Object> props = new HashMap<>();
        String problem = null;
        try {
            transport = UdpTransport.open(config.bindAddress(), config.port(), config.receiveBufferBytes(), NAME);
            listening = "listening on " + transport.localAddress();
            props.put(PORT_PROPERTY, transport.localPort());
            LOG.info("{} {} (receive buffer {} bytes)", NAME, listening, transport.receiveBufferSize());
        } catch (IOException | RuntimeException e) {
            problem = "cannot listen on " + config.bindAddress() + ":" + config.port() + ": " + e.getMessage();
            listening = problem;
            LOG.error("{} {}", NAME, problem);
        }
        start(bundleContext, props);
        rejects = new RejectCounter(context());
        handler = new FrameHandler(context(), this, rejects);
        if (transport != null) {
            transport.start(handler);
        } else {
            context().event(EventKind.PROBLEM, problem);
        }
    }

    @Deactivate
    void deactivate() {
        if (transport != null) {
            transport.close();
        }
        stop(); // removes the bus devices one by one, each removal announced, then the driver
    }

    @Override
    public AmicaBusDevice find(AmicaAddress address) {
        return nodes.get(address);
    }

    @Override
    public AmicaBusDevice create(AmicaAddress address, KeepAlive keepAlive, InetSocketAddress from, Instant at) {
        AmicaBusDevice device = new AmicaBusDevice(context(), address, keepAlive, from, this);
        nodes.put(address, device);
        return addDevice(device);
    }

    @Override
    protected void onDeviceRemoved(AbstractDevice device) {
        if (device instanceof AmicaBusDevice bus) {
            nodes.remove(bus.address(), bus);
        }
    }

    @Override
    public void send(AmicaBusDevice device, byte[] payload, InetSocketAddress to) {
        AmicaAddress node = device.address();
        byte[] frame = AmicaCodec.encode(new AmicaFrame(node.netgroup(), AmicaCodec.PLATFORM_ADDRESS,
                node.address(), sequence.getAndIncrement() & 0xFF, payload));
        UdpTransport t = transport;
        if (t == null) {
            context().reporter().packet(Direction.SENT, "node " + node, frame, "not sent: " + listening);
            return;
        }
        t.send(frame, to, (bytes, target, failure) -> {
            String where = "node " + node + " via " + target.getAddress().getHostAddress() + ":" + target.getPort();
            if (failure == null) {
                sent.incrementAndGet();
                context().reporter().packet(Direction.SENT, where, bytes, "");
            } else {
                context().reporter().packet(Direction.SENT, where, bytes, "send failed: " + failure.getMessage());
            }
        });
    }

    @Override
    public List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("status", listening, "socket state"));
        out.add(Parameter.readOnly("nodes", nodes.size(), "known nodes"));
        out.add(Parameter.readOnly("received", handler == null ? 0 : handler.received(), "datagrams received"));
        out.add(Parameter.readOnly("sent", sent.get(), "frames sent to nodes"));
        out.addAll(rejects == null ? List.of() : rejects.parameters());
        return out;
    }
}
