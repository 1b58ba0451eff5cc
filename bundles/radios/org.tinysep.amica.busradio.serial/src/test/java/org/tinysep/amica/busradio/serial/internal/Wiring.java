package org.tinysep.amica.busradio.serial.internal;

import java.time.Instant;
import java.util.List;
import java.util.function.UnaryOperator;
import org.tinysep.amica.busradio.base.AmicaNodes;
import org.tinysep.amica.busradio.base.FrameHandler;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** A driver context with in-memory logs, and frames as a node sends them; for tests without a framework. */
final class Wiring {

    static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    final RecordingLogs logs = new RecordingLogs(() -> T0);
    final DriverContext context;

    Wiring(String driverName) {
        context = new DriverContext(null, "driver-uid", driverName, logs.reporter(), new PlatformClock(() -> T0));
    }

    /** The shared bus radio parts, as a driver wires them. */
    record Parts<R>(RejectCounter<RejectReason> rejects, AmicaNodes<R> nodes, FrameHandler<R> handler) {
    }

    /** The base parts for a route type whose routes print as themselves, sending nowhere. */
    <R> Parts<R> parts() {
        RejectCounter<RejectReason> rejects = new RejectCounter<>(context, RejectReason.class,
                r -> r.description(), "input", "total");
        AmicaNodes<R> nodes = new AmicaNodes<>(context, "BusRadioAmicaSerial", new AmicaNodes.Transport<R>() {
            @Override
            public void transmit(byte[] frame, R route, AmicaNodes.Outcome outcome) {
                outcome.done("not sent: test");
            }

            @Override
            public String describe(R route) {
                return String.valueOf(route);
            }
        }, UnaryOperator.identity());
        return new Parts<>(rejects, nodes, new FrameHandler<>(context, nodes, rejects));
    }

    List<String> events(EventKind kind) {
        return logs.events().stream().filter(e -> e.kind() == kind).map(EventEntry::message).toList();
    }

    static byte[] frame(int netgroup, int address, int seq, AmicaPayload payload) {
        return AmicaCodec.encode(new AmicaFrame(netgroup, address, 0, seq, AmicaPayloads.encode(payload)));
    }

    static KeepAlive keepAlive(AmicaNodeType... types) {
        return new KeepAlive(120, 2900, 1, AmicaNodeType.productId(List.of(types)), 4242);
    }

    static byte[] concat(byte[]... parts) {
        int n = 0;
        for (byte[] p : parts) {
            n += p.length;
        }
        byte[] out = new byte[n];
        int at = 0;
        for (byte[] p : parts) {
            System.arraycopy(p, 0, out, at, p.length);
            at += p.length;
        }
        return out;
    }
}
