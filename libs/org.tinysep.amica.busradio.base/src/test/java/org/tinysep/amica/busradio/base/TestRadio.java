package org.tinysep.amica.busradio.base;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * The base parts wired like a bus radio driver wires them, without a framework: a route is a plain string and the
 * transport records what it is asked to send (our own {@link AmicaNodes.Transport} contract).
 */
final class TestRadio implements AmicaNodes.Transport<String> {

    static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    final RecordingLogs logs = new RecordingLogs(() -> T0);
    final DriverContext context =
            new DriverContext(null, "driver-uid", "BusRadioAmicaTest", logs.reporter(), new PlatformClock(() -> T0));
    final RejectCounter<RejectReason> rejects = new RejectCounter<>(context, RejectReason.class,
            r -> r.description(), "datagram", "datagrams rejected in total");
    final AmicaNodes<String> nodes = new AmicaNodes<>(context, "BusRadioAmicaTest", this, UnaryOperator.identity());
    final FrameHandler<String> handler = new FrameHandler<>(context, nodes, rejects);
    final List<byte[]> transmitted = new ArrayList<>();
    final List<String> routes = new ArrayList<>();
    /** How often a route was formatted for people (issue 29: not once per frame). */
    int describes;
    /** The outcome the next transmissions report; null = sent. */
    String failure;

    @Override
    public void transmit(byte[] frame, String route, AmicaNodes.Outcome outcome) {
        transmitted.add(frame);
        routes.add(route);
        outcome.done(failure);
    }

    @Override
    public String describe(String route) {
        describes++;
        return "route " + route;
    }

    void feed(byte[] datagram, String from) {
        handler.datagram(datagram, datagram.length, from);
    }

    static byte[] frame(int netgroup, int source, byte[] payload) {
        return AmicaCodec.encode(new AmicaFrame(netgroup, source, 0, 7, payload));
    }

    static byte[] keepAlive(AmicaNodeType... types) {
        return AmicaPayloads.encode(new KeepAlive(60, 3000, 1, AmicaNodeType.productId(List.of(types)), 1234));
    }
}
