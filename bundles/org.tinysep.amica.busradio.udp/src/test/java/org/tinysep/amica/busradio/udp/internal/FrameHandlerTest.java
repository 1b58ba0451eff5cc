package org.tinysep.amica.busradio.udp.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetSocketAddress;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;

/** The bus radio's decisions per datagram, without sockets or framework: what it creates, forwards, rejects. */
class FrameHandlerTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private static final InetSocketAddress FROM = new InetSocketAddress("127.0.0.1", 40000);

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final DriverContext context =
            new DriverContext(null, "driver-uid", "BusRadioAmicaUdp", logs.reporter(), new PlatformClock(() -> T0));
    private final Map<AmicaAddress, AmicaBusDevice> nodes = new HashMap<>();
    private final RejectCounter rejects = new RejectCounter(context);
    private final FrameHandler handler = new FrameHandler(context, new FrameHandler.Nodes() {
        @Override
        public AmicaBusDevice find(AmicaAddress address) {
            return nodes.get(address);
        }

        @Override
        public AmicaBusDevice create(AmicaAddress address, KeepAlive keepAlive, InetSocketAddress from, Instant at) {
            AmicaBusDevice d = new AmicaBusDevice(context, address, keepAlive, from, (dev, frame, to) -> { });
            nodes.put(address, d);
            return d;
        }
    }, rejects);

    private static byte[] frame(int netgroup, int source, byte[] payload) {
        return AmicaCodec.encode(new AmicaFrame(netgroup, source, 0, 7, payload));
    }

    private static byte[] keepAlive(AmicaNodeType... types) {
        return AmicaPayloads.encode(new KeepAlive(60, 3000, 1, AmicaNodeType.productId(List.of(types)), 1234));
    }

    private void feed(byte[] datagram) {
        handler.datagram(datagram, datagram.length, FROM);
    }

    @Test
    void keepAliveFromUnknownNodeCreatesOneBusDeviceWithItsTypes() {
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR)));
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR)));

        assertEquals(Set.of(new AmicaAddress(1, 17)), nodes.keySet());
        assertEquals(Set.of("movement", "door"), nodes.get(new AmicaAddress(1, 17)).nodeTypes());
    }

    @Test
    void payloadsOfAKnownNodeReachItsListenersAsCopies() {
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)));
        AmicaBusDevice node = nodes.get(new AmicaAddress(1, 17));
        List<byte[]> got = new ArrayList<>();
        node.connect((src, payload, at) -> {
            got.add(payload);
            payload[0] = 0; // a listener scribbling on its copy must not affect the next one
        });
        node.connect((src, payload, at) -> got.add(payload));

        byte[] motion = AmicaPayloads.encode(new MotionDetection(true));
        feed(frame(1, 17, motion));

        assertEquals(2, got.size());
        assertArrayEquals(motion, got.get(1));
    }

    @Test
    void nonKeepAliveFromUnknownNodeIsRejectedAndCreatesNothing() {
        feed(frame(1, 18, AmicaPayloads.encode(new MotionDetection(true))));

        assertTrue(nodes.isEmpty());
        assertEquals(1, rejects.count(RejectReason.UNKNOWN_NODE));
        PacketEntry logged = logs.packets().get(0);
        assertTrue(logged.note().startsWith("UNKNOWN_NODE"), logged.note());
    }

    @Test
    void everyKindOfBadInputIsCountedUnderItsReasonAndTheNextGoodFrameStillWorks() {
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)));
        byte[] good = frame(1, 17, AmicaPayloads.encode(new MotionDetection(true)));

        byte[] badChecksum = good.clone();
        badChecksum[6] ^= 0x55;
        feed(badChecksum);
        feed(new byte[] {4, (byte) 0xA1, 17, 0});                      // truncated
        feed(new byte[600]);                                            // oversize datagram
        feed(frame(1, 17, new byte[] {9, 9, 0, 1}));                    // unknown payload
        feed(frame(1, 17, new byte[] {100, 5, 0, 7}));                  // motion value out of range
        byte[] badHeader = good.clone();
        badHeader[1] = 0x42;
        feed(badHeader);

        assertEquals(1, rejects.count(RejectReason.BAD_CHECKSUM));
        assertEquals(1, rejects.count(RejectReason.TRUNCATED));
        assertEquals(1, rejects.count(RejectReason.OVERSIZE));
        assertEquals(1, rejects.count(RejectReason.UNKNOWN_PAYLOAD));
        assertEquals(1, rejects.count(RejectReason.BAD_VALUE));
        assertEquals(1, rejects.count(RejectReason.BAD_HEADER));
        assertEquals(6, rejects.total());

        List<Boolean> motions = new ArrayList<>();
        nodes.get(new AmicaAddress(1, 17)).connect((src, payload, at) -> motions.add(payload[3] == 1));
        feed(good);
        assertEquals(List.of(true), motions, "a valid frame right after garbage is delivered");
        assertEquals(1, nodes.size(), "no device created or lost");
    }

    @Test
    void eachRejectReasonIsReportedOnceToTheEventLogButEveryPacketIsLogged() {
        byte[] truncated = {4, (byte) 0xA1, 17, 0};
        for (int i = 0; i < 50; i++) {
            feed(truncated);
        }
        long problems = logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).count();
        assertEquals(1, problems);
        assertEquals(50, rejects.count(RejectReason.TRUNCATED));
        assertEquals(50, logs.packets().size());
        assertNotNull(logs.packets().get(49).note());
    }
}
