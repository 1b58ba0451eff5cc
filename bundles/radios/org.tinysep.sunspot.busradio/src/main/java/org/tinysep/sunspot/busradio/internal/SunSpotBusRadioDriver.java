package org.tinysep.sunspot.busradio.internal;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.intake.RejectTotals;
import org.tinysep.device.support.intake.SourceGate;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.time.PlatformTicker;
import org.tinysep.sunspot.protocol.RejectReason;

/**
 * Bus Radio Sun SPOT (thesis 4.4.1.3): one bus device per Sun SPOT address, created on the first valid packet of
 * any kind, providing {@code BusRadioSunSpotProvider}. Packets arrive on up to three links configured together
 * (UDP, serial basestation, Sun SPOT SDK in-process) and take one path through a shared {@link PacketHandler} and
 * node table. The Driver service carries the bound UDP port ({@value #PORT_PROPERTY}) when the UDP link is on.
 */
@Component(service = {}, immediate = true, configurationPid = SunSpotBusRadioDriver.PID)
@Designate(ocd = BusRadioSunSpotConfig.class)
public final class SunSpotBusRadioDriver extends AbstractDriver {

    public static final String PID = "org.tinysep.sunspot.busradio";
    public static final String NAME = "BusRadioSunSpot";
    public static final String PORT_PROPERTY = "tinysep.udp.port";
    /** Pause between attempts to open a missing serial port or SDK radiogram port. */
    static final Duration REOPEN_EVERY = Duration.ofSeconds(5);
    /** A tick waits at most this long for the packets queued before it (past the slow-listener limit). */
    static final Duration TICK_WAIT = Duration.ofSeconds(2);

    private volatile SunSpotLinks links;
    private volatile SunSpotNodes nodes;
    private volatile PacketHandler handler;
    private volatile RejectCounter<RejectReason> rejects;
    private volatile SourceGate gate;
    private volatile PlatformTicker ticker;
    /** One ordered queue and dispatcher for every bus device's listeners: a slow listener never stalls a link */
    private volatile OrderedDelivery delivery;

    public SunSpotBusRadioDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, BusRadioSunSpotConfig config) {
        links = new SunSpotLinks(LinkSettings.of(config), SdkRadiograms.OPENER, REOPEN_EVERY, NAME);
        links.bind();
        Map<String, Object> props = new HashMap<>();
        links.udpPort().ifPresent(port -> props.put(PORT_PROPERTY, port));
        start(bundleContext, props);
        List<String> problems = new ArrayList<>();
        NodePolicy policy = NodePolicy.of(config.silentAfterIntervals(), 0, config.maxNodes(), problems);
        try {
            gate = SourceGate.of(config.udpBindAddress(), config.allowedSources(), config.sourceRateLimit());
        } catch (IllegalArgumentException e) { // a bad allow-list must not open the radio to everyone
            gate = SourceGate.of(config.udpBindAddress(), "", config.sourceRateLimit());
            problems.add(e.getMessage() + "; allowing only 127.0.0.1, ::1");
        }
        problems.forEach(p -> context().event(EventKind.PROBLEM, p));
        rejects = new RejectCounter<>(context(), RejectReason.class, r -> r.description(), "packet",
                "packets (or serial byte runs) rejected in total");
        nodes = new SunSpotNodes(context(), NAME, this::addDevice);
        nodes.policy(policy);
        delivery = new OrderedDelivery(context(), "The Sun SPOT radio");
        nodes.delivery(delivery);
        handler = new PacketHandler(context(), nodes, rejects);
        nodes.restore(savedDevices()); // known nodes as they were, before the links open (docs/backup.md)
        links.gate(gate, p -> context().event(EventKind.PROBLEM, p));
        links.start(handler, nodes, context());
        PacketHandler h = handler;
        OrderedDelivery d = delivery;
        ticker = new PlatformTicker(bundleContext, NAME, now -> { // sensor health in platform time
            d.awaitDelivered(TICK_WAIT); // what was queued before the tick reached its listeners (a stuck one aside)
            h.tick(now);
        });
    }

    @Deactivate
    void deactivate() {
        stop(ticker, links, delivery); // then removes the bus devices one by one (each leaves the node table), the driver
    }

    @Override
    public List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        if (links != null) {
            out.addAll(links.parameters());
        }
        out.add(Parameter.readOnly("nodes", nodes == null ? 0 : nodes.size(), "known Sun SPOTs"));
        out.add(Parameter.readOnly("received", handler == null ? 0 : handler.received(),
                "packets received on all links"));
        out.addAll(rejects == null ? List.of() : rejects.parameters());
        out.addAll(gate == null ? List.of() : gate.parameters());
        out.addAll(nodes == null ? List.of() : nodes.parameters());
        out.addAll(delivery == null ? List.of() : delivery.parameters());
        return RejectTotals.summed(out); // rejected = every rejected.<reason>, the gate's and node_cap included

    }
}
