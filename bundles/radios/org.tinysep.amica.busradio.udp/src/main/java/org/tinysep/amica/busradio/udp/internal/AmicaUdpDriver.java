package org.tinysep.amica.busradio.udp.internal;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.amica.busradio.base.AmicaNodes;
import org.tinysep.amica.busradio.base.FrameHandler;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.intake.RejectTotals;
import org.tinysep.device.support.intake.SourceGate;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.time.PlatformTicker;
import org.tinysep.link.udp.DatagramLink;

/**
 * Bus Radio AmICA UDP/IP (thesis 4.4.1.2): listens on a UDP port and hands each datagram to the shared AmICA bus
 * radio logic ({@code org.tinysep.amica.busradio.base}), which creates one bus device per node on the node's first
 * keep-alive and forwards later payloads to it. This class is the transport: a node's route is the UDP address
 * it last sent from. Its Driver service carries the bound port ({@value #PORT_PROPERTY}).
 * <p>
 * Lock-step: every platform tick first hands over the datagrams still waiting in the socket, on the tick's thread,
 * stamped with the platform time before the tick (what the receive thread would have stamped). A frame a simulator
 * sent before a {@code TICK} is therefore handled, and the commands it causes are sent, before that TICK's
 * {@code DONE}, however late the receive thread gets the CPU (docs/time-sync.md).
 */
@Component(service = {}, immediate = true, configurationPid = AmicaUdpDriver.PID)
@Designate(ocd = BusRadioUdpConfig.class)
public final class AmicaUdpDriver extends AbstractDriver implements AmicaNodes.Transport<InetSocketAddress> {

    public static final String PID = "org.tinysep.amica.busradio.udp";
    public static final String NAME = "BusRadioAmicaUdp";
    public static final String PORT_PROPERTY = "tinysep.udp.port";

    private static final Logger LOG = LoggerFactory.getLogger(AmicaUdpDriver.class);

    private RejectCounter<RejectReason> rejects;
    private AmicaNodes<InetSocketAddress> nodes;
    private FrameHandler<InetSocketAddress> handler;
    private DatagramLink transport;
    private String listening;
    private PlatformTicker ticker;
    /** One ordered queue and dispatcher for every bus device's listeners */
    private org.tinysep.device.support.delivery.OrderedDelivery delivery;
    private SourceGate gate;
    /** The platform time of the last tick: what a frame arriving before the next tick is stamped. */
    private Instant beforeTick;

    public AmicaUdpDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, BusRadioUdpConfig config) {
        Map<String, Object> props = new HashMap<>();
        List<String> settingProblems = new ArrayList<>();
        NodePolicy policy = NodePolicy.of(config.silentAfterIntervals(), config.lowBatteryMillivolts(),
                config.maxNodes(), settingProblems);
        try {
            gate = SourceGate.of(config.bindAddress(), config.allowedSources(), config.sourceRateLimit());
        } catch (IllegalArgumentException e) { // a bad allow-list must not open the radio to everyone
            gate = SourceGate.of(config.bindAddress(), "", config.sourceRateLimit());
            settingProblems.add(e.getMessage() + "; allowing only " + String.join(", ", "127.0.0.1", "::1"));
        }
        String problem = null;
        String why = null;
        try {
            transport = DatagramLink.open(config.bindAddress(), config.port(), config.receiveBufferBytes(),
                    NAME + "-receive");
            listening = "listening on " + transport.localAddress();
            props.put(PORT_PROPERTY, transport.localPort());
            LOG.info("{} {} (receive buffer {} bytes)", NAME, listening, transport.receiveBufferSize());
        } catch (IOException | RuntimeException e) {
            why = e.getMessage();
            problem = "cannot listen on " + config.bindAddress() + ":" + config.port() + ": " + why;
            listening = problem;
            LOG.error("{} {}", NAME, problem);
        }
        start(bundleContext, props);
        rejects = new RejectCounter<>(context(), RejectReason.class, r -> r.description(), "datagram",
                "datagrams rejected in total");
        nodes = new AmicaNodes<>(context(), NAME, this, this::addDevice);
        nodes.policy(policy);
        delivery = UdpDelivery.open(context(), config.slowListenerMillis(), settingProblems);
        nodes.delivery(delivery); // the receive thread only decodes and queues; a slow listener never stalls it
        handler = new FrameHandler<>(context(), nodes, rejects);
        settingProblems.forEach(p -> context().event(EventKind.PROBLEM, p));
        if (gate.enforced()) {
            LOG.info("{} bound to {}: {}", NAME, config.bindAddress(), gate.describe());
        }
        nodes.restore(savedDevices()); // known nodes as they were, before the first datagram (docs/backup.md)
        if (transport != null) {
            transport.start(this::datagram);
            ticker = new PlatformTicker(bundleContext, NAME, this::tick);
        } else { // a caregiver notice and a WARNING under the banner (docs/security.md, "Nothing reduces monitoring")
            context().event(EventKind.PROBLEM, "Monitoring reduced: the AmICA radio cannot listen on "
                    + config.bindAddress() + ":" + config.port() + " (" + why + "): no AmICA "
                    + "sensor is heard. Another program may hold the port: stop it, or set another port in "
                    + "etc/" + PID + ".cfg, then restart TinySEP");
        }
    }

    /** Hands over the frames that arrived before this tick (called by the platform ticker, never concurrently). */
    private void tick(Instant now) {
        Instant stamp = beforeTick == null ? now : beforeTick;
        beforeTick = now;
        transport.drain((data, length, from) -> datagram(data, length, from, stamp));
        // lock-step: what was queued before this tick reaches the listeners before it goes on (DONE); a listener
        // known to be slow has its own queue and is not waited for
        delivery.awaitDelivered(UdpDelivery.TICK_WAIT);
        nodes.checkHealth(now);
        handler.flushRejects();
    }

    private void datagram(byte[] data, int length, InetSocketAddress from) {
        datagram(data, length, from, null);
    }

    /** The source gate first (allow-list, rate limit; docs/security.md), then the shared frame logic. */
    private void datagram(byte[] data, int length, InetSocketAddress from, Instant stamp) {
        SourceGate.Verdict verdict = gate.check(from.getAddress());
        if (verdict != SourceGate.Verdict.PASS) {
            refused(verdict, data, length, from);
            return;
        }
        handler.datagram(data, length, from, stamp);
    }

    private void refused(SourceGate.Verdict verdict, byte[] data, int length, InetSocketAddress from) {
        String first = gate.firstRefusal(verdict, from.getAddress());
        if (first != null) {
            LOG.warn("{}: {}", NAME, first);
            context().event(EventKind.PROBLEM, first);
        }
        String why = SourceGate.why(verdict, from.getAddress());
        handler.refused(why, data, length, from);
    }

    @Deactivate
    void deactivate() {
        stop(ticker, transport, delivery); // then removes the bus devices one by one (each leaves the node table), the driver
    }

    @Override
    public void transmit(byte[] frame, InetSocketAddress to, AmicaNodes.Outcome outcome) {
        DatagramLink t = transport;
        if (t == null) {
            outcome.done("not sent: " + listening);
            return;
        }
        t.send(frame, to, (bytes, target, failure) ->
                outcome.done(failure == null ? null : "send failed: " + failure.getMessage()));
    }

    @Override
    public String describe(InetSocketAddress route) {
        return route.getAddress().getHostAddress() + ":" + route.getPort();
    }

    @Override
    public List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("status", listening, "socket state"));
        out.add(Parameter.readOnly("nodes", nodes == null ? 0 : nodes.size(), "known nodes"));
        out.add(Parameter.readOnly("received", handler == null ? 0 : handler.received(), "datagrams received"));
        out.add(Parameter.readOnly("sent", nodes == null ? 0 : nodes.sent(), "frames sent to nodes"));
        out.addAll(rejects == null ? List.of() : rejects.parameters());
        out.addAll(gate == null ? List.of() : gate.parameters());
        out.addAll(nodes == null ? List.of() : nodes.parameters());
        out.addAll(delivery == null ? List.of() : delivery.parameters());
        return RejectTotals.summed(out); // rejected = every rejected.<reason>, the gate's and node_cap included

    }
}
