package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.PacketEntry;

/** The bus radio's decisions per frame, without transport or framework: what it creates, forwards, rejects. */
class FrameHandlerTest {

    private static final String FROM = "127.0.0.1:40000";

    private final TestRadio radio = new TestRadio();

    private void feed(byte[] datagram) {
        radio.feed(datagram, FROM);
    }

    private AmicaBusDevice<String> node(int netgroup, int address) {
        return radio.nodes.find(new AmicaAddress(netgroup, address));
    }

    @Test
    void keepAliveFromUnknownNodeCreatesOneBusDeviceWithItsTypes() {
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR)));
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT, AmicaNodeType.DOOR)));

        assertEquals(Set.of(new AmicaAddress(1, 17)),
                radio.nodes.all().stream().map(AmicaBusDevice::address).collect(Collectors.toSet()));
        assertEquals(Set.of("movement", "door"), node(1, 17).nodeTypes());
        assertEquals("BusRadioAmicaTest", node(1, 17).type());
        assertEquals(FROM, node(1, 17).route());
    }

    @Test
    void aFrameTakenLateIsStampedWithTheTimeGivenButNeverEarlierThanTheLastStamp() {
        byte[] keepAlive = frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT));
        radio.handler.datagram(keepAlive, keepAlive.length, FROM, TestRadio.T0.minusSeconds(2));
        List<String> stamps = new ArrayList<>();
        node(1, 17).connect((src, payload, at) -> stamps.add(at.toString()));
        byte[] motion = frame(1, 17, AmicaPayloads.encode(new MotionDetection(true)));
        radio.handler.datagram(motion, motion.length, FROM, TestRadio.T0.minusSeconds(1)); // taken during a tick
        radio.handler.datagram(motion, motion.length, FROM); // now (T0)
        radio.handler.datagram(motion, motion.length, FROM, TestRadio.T0.minusSeconds(5)); // never backwards
        assertEquals(List.of("2026-11-22T09:59:59Z", "2026-11-22T10:00:00Z", "2026-11-22T10:00:00Z"), stamps);
    }

    @Test
    void payloadsOfAKnownNodeReachItsListenersAsCopies() {
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)));
        AmicaBusDevice<String> node = node(1, 17);
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

        assertTrue(radio.nodes.all().isEmpty());
        assertEquals(1, radio.rejects.count(RejectReason.UNKNOWN_NODE));
        PacketEntry logged = radio.logs.packets().get(0);
        assertTrue(logged.note().startsWith("UNKNOWN_NODE"), logged.note());
        assertEquals("route " + FROM, logged.origin());
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

        for (RejectReason r : List.of(RejectReason.BAD_CHECKSUM, RejectReason.TRUNCATED, RejectReason.OVERSIZE,
                RejectReason.UNKNOWN_PAYLOAD, RejectReason.BAD_VALUE, RejectReason.BAD_HEADER)) {
            assertEquals(1, radio.rejects.count(r), r.name());
        }
        assertEquals(6, radio.rejects.total());

        List<Boolean> motions = new ArrayList<>();
        node(1, 17).connect((src, payload, at) -> motions.add(payload[3] == 1));
        feed(good);
        assertEquals(List.of(true), motions, "a valid frame right after garbage is delivered");
        assertEquals(1, radio.nodes.size(), "no device created or lost");
        assertEquals(8, radio.handler.received());
    }

    @Test
    void eachRejectReasonIsReportedOnceToTheEventLogButEveryPacketIsLogged() {
        byte[] truncated = {4, (byte) 0xA1, 17, 0};
        for (int i = 0; i < 50; i++) {
            feed(truncated);
        }
        List<String> problems = radio.logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM)
                .map(e -> e.message()).toList();
        assertEquals(1, problems.size());
        assertTrue(problems.get(0).startsWith("rejected datagram from route " + FROM + ": TRUNCATED ("),
                problems.get(0));
        assertEquals(50, radio.rejects.count(RejectReason.TRUNCATED));
        assertEquals(50, radio.logs.packets().size());
        assertNotNull(radio.logs.packets().get(49).note());
    }

    @Test
    void framesFromAStreamAndRunsItRejectedAreHandledLikeDatagrams() {
        byte[] ka = frame(2, 5, keepAlive(AmicaNodeType.HEATER));
        radio.handler.rejected(RejectReason.BAD_HEADER, "BAD_HEADER (x): 3 bytes skipped", new byte[] {1, 2, 3}, "tty");
        radio.handler.frame(decode(ka), ka, "tty");

        assertEquals(1, radio.rejects.count(RejectReason.BAD_HEADER));
        assertEquals(Set.of("heater"), node(2, 5).nodeTypes());
        List<PacketEntry> packets = radio.logs.packets();
        assertEquals("BAD_HEADER (x): 3 bytes skipped", packets.get(0).note());
        assertArrayEquals(new byte[] {1, 2, 3}, packets.get(0).bytes());
        assertEquals("node 2.5 via route tty", packets.get(1).origin());
        assertArrayEquals(ka, packets.get(1).bytes());
        assertNull(radio.nodes.find(new AmicaAddress(2, 6)));
    }

    private static AmicaFrame decode(byte[] frame) {
        try {
            return AmicaCodec.decode(frame, 0, frame.length);
        } catch (AmicaProtocolException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void theRouteIsFormattedOncePerNodeAndRouteNotPerFrame() {
        feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)));
        feed(frame(1, 18, keepAlive(AmicaNodeType.MOVEMENT)));
        int before = radio.describes;
        byte[] motion = AmicaPayloads.encode(new MotionDetection(true));
        for (int i = 0; i < 1_000; i++) {
            feed(frame(1, 17 + i % 2, motion));
        }
        radio.feed(frame(1, 17, motion), "127.0.0.1:40001"); // the node heard by another route
        assertTrue(radio.describes - before <= 3, "routes formatted for 1,001 frames of 2 nodes by 2 routes: "
                + (radio.describes - before));
        List<PacketEntry> packets = radio.logs.packets();
        assertEquals(1_003, packets.size());
        assertEquals("node 1.17 via route " + FROM, packets.get(2).origin());
        assertEquals("node 1.18 via route " + FROM, packets.get(3).origin());
        assertEquals("node 1.17 via route 127.0.0.1:40001", packets.get(1_002).origin());
    }
}
