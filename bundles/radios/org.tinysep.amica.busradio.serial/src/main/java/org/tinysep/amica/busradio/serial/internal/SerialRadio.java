package org.tinysep.amica.busradio.serial.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.amica.busradio.base.AmicaBusDevice;
import org.tinysep.amica.busradio.base.AmicaNodes;
import org.tinysep.amica.busradio.base.FrameHandler;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.intake.RejectTotals;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.serial.support.SerialPortLink;

/**
 * The serial bus radio of one port, without the framework: the port link, the stream decoder, the shared AmICA
 * node logic, and what happens when the port comes and goes. A lost port is reported (driver {@code status},
 * a {@code PROBLEM} event) and turns every bus device of the port OFFLINE; the link reopens by itself, the
 * decoder starts afresh, and each device is ONLINE again with its next packet. Commands to nodes go out through
 * the same port. The route of every node is the link.
 */
final class SerialRadio implements SerialPortLink.Listener, AmicaNodes.Transport<SerialPortLink>, AutoCloseable {

    /** Type of the bus devices (the driver name adds the port). */
    static final String DEVICE_TYPE = "BusRadioAmicaSerial";
    private static final Logger LOG = LoggerFactory.getLogger(SerialRadio.class);

    private final DriverContext context;
    private final SerialSettings settings;
    private final RejectCounter<RejectReason> rejects;
    private final AmicaNodes<SerialPortLink> nodes;
    private final FrameHandler<SerialPortLink> handler;
    private final SerialPortLink link;
    private final StreamFrames<SerialPortLink> frames;
    /** One ordered queue and dispatcher for every bus device's listeners: the read thread only decodes */
    private final org.tinysep.device.support.delivery.OrderedDelivery delivery;
    private volatile long outages;

    /**
     * @param register registers a new bus device with the driver; the identity without a framework
     */
    SerialRadio(DriverContext context, SerialSettings settings,
            UnaryOperator<AmicaBusDevice<SerialPortLink>> register) {
        this.context = context;
        this.settings = settings;
        this.rejects = new RejectCounter<>(context, RejectReason.class, r -> r.description(), "input",
                "skipped byte runs and frames rejected in total");
        this.nodes = new AmicaNodes<>(context, DEVICE_TYPE, this, register);
        this.delivery = new org.tinysep.device.support.delivery.OrderedDelivery(context, "The AmICA serial radio on "
                + settings.port());
        nodes.delivery(delivery);
        this.handler = new FrameHandler<>(context, nodes, rejects);
        this.link = new SerialPortLink(settings.port(), settings.baudRate(), settings.reopenEvery(),
                context.driverName(), this);
        this.frames = new StreamFrames<>(handler, link);
    }

    /** Re-creates the bus devices of the nodes known before the restart; call before {@link #start()}. */
    void restore(java.util.List<org.tinysep.api.backup.ComponentBackup> saved) {
        nodes.restore(saved);
    }

    /** Opens the port on the link's thread; returns at once. */
    void start() {
        link.start();
    }

    @Override
    public void bytes(byte[] buf, int len) {
        frames.accept(buf, len);
    }

    @Override
    public void opened(String port) {
        frames.reset();
        context.event(EventKind.STATUS, "port " + port + " open at " + settings.baudRate() + " baud"
                + (outages > 0 ? " again; its bus devices come back ONLINE with their next packet" : ""));
    }

    @Override
    public void lost(String port, String reason) {
        outages++;
        frames.reset();
        String detail = "port " + port + " unavailable: " + reason;
        LOG.warn("{}: {}", context.driverName(), detail);
        context.event(EventKind.PROBLEM, detail + "; " + nodes.size() + " bus device(s) OFFLINE; reopening every "
                + settings.reopenEvery().toSeconds() + " s by itself"); // cause before effect in the event log
        nodes.offline(detail);
    }

    @Override
    public void transmit(byte[] frame, SerialPortLink route, AmicaNodes.Outcome outcome) {
        route.write(frame, (data, failure) -> outcome.done(failure));
    }

    @Override
    public String describe(SerialPortLink route) {
        return route.portPath();
    }

    /** Sets the health and capacity settings of the nodes. */
    void policy(NodePolicy policy) {
        nodes.policy(policy);
        nodes.realSilenceGuard(REAL_SILENCE_GUARD); // frames arrive on the port's thread, not on the tick
    }

    /** Real time a node must also be silent for (lock-step virtual time runs far ahead of a lagging reader). */
    static final java.time.Duration REAL_SILENCE_GUARD = java.time.Duration.ofSeconds(2);

    /** A platform tick: silent nodes go OFFLINE, the summary of rejected input not kept is written. */
    void tick(Instant now) {
        nodes.checkHealth(now);
        handler.flushRejects();
    }

    List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("status", settings.port() + " " + link.state(), "serial port state"));
        out.add(Parameter.readOnly("port", settings.port(), "serial port path"));
        out.add(Parameter.readOnly("baudRate", settings.baudRate(), "bits per second, 8N1"));
        out.add(Parameter.readOnly("reopenSeconds", settings.reopenEvery().toSeconds(),
                "pause between attempts to open a missing or lost port"));
        out.add(Parameter.readOnly("outages", outages, "times the port could not be opened or was lost"));
        out.add(Parameter.readOnly("nodes", nodes.size(), "known nodes"));
        out.add(Parameter.readOnly("bytesReceived", link.bytesRead(), "bytes read from the port"));
        out.add(Parameter.readOnly("received", handler.received(), "frames found in the byte stream"));
        out.add(Parameter.readOnly("skippedBytes", frames.skippedBytes(), "bytes skipped while resynchronising"));
        out.add(Parameter.readOnly("sent", nodes.sent(), "frames sent to nodes"));
        out.add(Parameter.readOnly("sendFailures", nodes.failed(), "frames not sent (port closed or write failed)"));
        out.addAll(rejects.parameters());
        out.addAll(nodes.parameters());
        out.addAll(delivery.parameters());
        return RejectTotals.summed(out); // rejected = every rejected.<reason>, node_cap included

    }

    boolean isOpen() {
        return link.isOpen();
    }

    /** Closes the port; the driver then removes the bus devices. */
    @Override
    public void close() {
        link.close();
        delivery.close();
    }
}
