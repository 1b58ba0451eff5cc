package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.fail;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.UnaryOperator;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/**
 * The bus radio's shared parts wired as the driver wires them, without a framework: in-memory logs, a node table
 * that does not register services, one packet handler; and the links a test opens on them, closed with the bus (a
 * test's {@code @AutoClose} field).
 */
final class TestBus implements AutoCloseable {

    /** How long a test waits for a link's thread to get somewhere. */
    static final Duration TIMEOUT = Duration.ofSeconds(10);

    static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    static final SunSpotAddress SPOT_A = SunSpotAddress.parse("0014.4F01.0000.1234");
    static final SunSpotAddress SPOT_B = SunSpotAddress.parse("0014.4F01.0000.5678");

    final RecordingLogs logs = new RecordingLogs(() -> T0);
    final DriverContext context =
            new DriverContext(null, "driver-uid", "BusRadioSunSpot", logs.reporter(), new PlatformClock(() -> T0));
    final RejectCounter<RejectReason> rejects = new RejectCounter<>(context, RejectReason.class,
            r -> r.description(), "packet",
            "packets (or serial byte runs) rejected in total");
    final SunSpotNodes nodes = new SunSpotNodes(context, "BusRadioSunSpot", UnaryOperator.identity());
    final PacketHandler handler = new PacketHandler(context, nodes, rejects);
    final Feed feed = new Feed(handler, nodes, context);
    private final List<AutoCloseable> links = new ArrayList<>();

    /** @return the link, closed when the test ends (closing a link twice does no harm) */
    <L extends AutoCloseable> L closing(L link) {
        links.add(link);
        return link;
    }

    @Override
    public void close() throws Exception {
        for (AutoCloseable link : links) {
            link.close();
        }
    }

    void feed(byte[] datagram, String from) {
        handler.datagram(datagram, datagram.length, from);
    }

    SunSpotBusDevice node(SunSpotAddress address) {
        return nodes.find(address);
    }

    List<String> problems() {
        return logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).map(EventEntry::message).toList();
    }

    static byte[] frame(SunSpotAddress source, SunSpotPayload payload) {
        return SunSpotCodec.encode(SunSpotFrame.of(source, SunSpotPayloads.encode(payload)));
    }

    /** Polls until the condition holds; fails after the timeout (no timed assertions). */
    static void await(String what, Duration timeout, BooleanSupplier condition) {
        long end = System.nanoTime() + timeout.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                fail("timed out after " + timeout + " waiting for " + what);
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted waiting for " + what);
            }
        }
    }
}
