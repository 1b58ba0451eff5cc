package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_B;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** The one decoder path and the node table, without transport or framework: what they create, forward, reject. */
class PacketHandlerTest {

    private static final String UDP = "udp 127.0.0.1:40000";

    private final TestBus bus = new TestBus();

    private void feed(byte[] datagram) {
        bus.feed(datagram, UDP);
    }

    @Test
    void firstPacketOfAnyKindCreatesTheBusDevice() {
        feed(frame(SPOT_A, new TemperatureStatus(21.5)));

        SunSpotBusDevice device = bus.node(SPOT_A);
        assertNotNull(device, "no keep-alive needed (thesis 4.4.1.3)");
        assertEquals(Set.of("temperature"), device.nodeTypes());
        assertEquals("0014.4F01.0000.1234", device.nodeAddress());
        assertEquals("BusRadioSunSpot", device.type());
        assertEquals(UDP, device.link());
        assertEquals(DeviceStatus.State.ONLINE, device.status().state());
        assertEquals(1, bus.nodes.size());
    }

    @Test
    void nodeTypesAccumulateAsNewSensorTypesArrive() {
        feed(frame(SPOT_A, new MovementDetection(true)));
        SunSpotBusDevice device = bus.node(SPOT_A);
        feed(frame(SPOT_A, new LightStatus(40)));
        feed(frame(SPOT_A, new MovementDetection(false, new Position(1, 2, 3))));
        feed(frame(SPOT_A, new LightStatus(41)));

        assertSame(device, bus.node(SPOT_A), "one bus device per address");
        assertEquals(Set.of("movement", "light-sensor"), device.nodeTypes());
        assertEquals(4, device.packets());
        assertEquals(1, bus.logs.events().stream().filter(e -> e.message().startsWith("node type light-sensor seen"))
                .count(), "a new type is announced once");
    }

    @Test
    void everyAddressGetsItsOwnDevice() {
        feed(frame(SPOT_A, new MovementDetection(true)));
        feed(frame(SPOT_B, new PetMovementDetection(true)));

        assertEquals(2, bus.nodes.size());
        assertEquals(Set.of("pet-collar"), bus.node(SPOT_B).nodeTypes());
        assertNotSame(bus.node(SPOT_A).uid(), bus.node(SPOT_B).uid());
    }

    @Test
    void listenersGetSensorTypeAndTheirOwnCopyOfThePayload() {
        feed(frame(SPOT_A, new TemperatureStatus(20.0)));
        SunSpotBusDevice device = bus.node(SPOT_A);
        List<String> got = new ArrayList<>();
        List<byte[]> payloads = new ArrayList<>();
        device.connect((src, type, payload, at) -> {
            got.add(src.nodeAddress() + " " + type + " " + at);
            payload[0] = 0; // scribbling on its copy must not affect the next listener
        });
        device.connect((BusRadioSunSpotProvider src, int type, byte[] payload, java.time.Instant at) ->
                payloads.add(payload));

        byte[] temp = SunSpotPayloads.encode(new TemperatureStatus(22.5));
        feed(SunSpotCodec.encode(SunSpotFrame.of(SPOT_A, temp)));

        assertEquals(List.of("0014.4F01.0000.1234 3 " + TestBus.T0), got);
        assertArrayEquals(temp, payloads.get(0));
    }

    @Test
    void aThrowingListenerDoesNotStopDelivery() {
        feed(frame(SPOT_A, new MovementDetection(true)));
        List<Integer> got = new ArrayList<>();
        bus.node(SPOT_A).connect((src, type, payload, at) -> {
            throw new IllegalStateException("listener bug");
        });
        bus.node(SPOT_A).connect((src, type, payload, at) -> got.add(type));
        feed(frame(SPOT_A, new MovementDetection(false)));
        feed(frame(SPOT_A, new MovementDetection(true)));
        assertEquals(List.of(2, 2), got);
    }

    @Test
    void badInputIsCountedPerReasonLoggedOnceAndCreatesNothing() {
        byte[] good = frame(SPOT_A, new LightStatus(50));
        byte[] badChecksum = good.clone();
        badChecksum[10] ^= 1;
        byte[] wrongType = SunSpotCodec.encode(new SunSpotFrame(SPOT_A, 3, SunSpotPayloads.encode(new LightStatus(5))));
        byte[] unknownType = SunSpotCodec.encode(SunSpotFrame.of(SPOT_A, new byte[] {9, 1, 0, 1}));
        byte[] badValue = SunSpotCodec.encode(SunSpotFrame.of(SPOT_A, new byte[] {4, 1, 0, 101}));
        for (byte[] bad : List.of(badChecksum, badChecksum, wrongType, unknownType, badValue, new byte[3])) {
            feed(bad);
        }

        assertNull(bus.node(SPOT_A), "bad input creates no device");
        assertEquals(2, bus.rejects.count(RejectReason.BAD_CHECKSUM));
        assertEquals(1, bus.rejects.count(RejectReason.TYPE_MISMATCH));
        assertEquals(1, bus.rejects.count(RejectReason.UNKNOWN_PAYLOAD));
        assertEquals(1, bus.rejects.count(RejectReason.BAD_VALUE));
        assertEquals(1, bus.rejects.count(RejectReason.TRUNCATED));
        assertEquals(6, bus.rejects.total());
        assertEquals(5, bus.problems().size(), "only the first of each reason is logged: " + bus.problems());
        assertTrue(bus.problems().get(0).contains("BAD_CHECKSUM") && bus.problems().get(0).contains(UDP),
                bus.problems().get(0));

        List<PacketEntry> packets = bus.logs.packets();
        assertEquals(6, packets.size(), "every packet is in the packet log");
        assertTrue(packets.get(0).note().startsWith("BAD_CHECKSUM"), packets.get(0).note());
        assertArrayEquals(badChecksum, packets.get(0).bytes());

        feed(good);
        assertNotNull(bus.node(SPOT_A), "a good packet after bad ones still creates the device");
        assertEquals("", bus.logs.packets().get(6).note());
        assertEquals("node 0014.4F01.0000.1234 via " + UDP, bus.logs.packets().get(6).origin());
        assertEquals(7, bus.handler.received());
    }

    @Test
    void badPayloadFromAKnownNodeAddsNoTypeAndReachesNoListener() {
        feed(frame(SPOT_A, new MovementDetection(true)));
        List<Integer> got = new ArrayList<>();
        bus.node(SPOT_A).connect((src, type, payload, at) -> got.add(type));
        feed(SunSpotCodec.encode(SunSpotFrame.of(SPOT_A, new byte[] {3, 1, 0x7F, 0})));
        assertEquals(Set.of("movement"), bus.node(SPOT_A).nodeTypes());
        assertEquals(List.of(), got);
        assertEquals(1, bus.rejects.count(RejectReason.BAD_VALUE));
    }

    @Test
    void personNodeFramesAreAcceptedAndImpossibleOnesCountedAsBadValues() {
        feed(frame(SPOT_B, new ButtonReport(1, true)));
        SunSpotBusDevice person = bus.node(SPOT_B);
        assertNotNull(person, "a person node (sensor type 6, protocol 2.2.0) is a Sun SPOT node like the others");
        assertEquals(Set.of("person"), person.nodeTypes());
        List<Integer> got = new ArrayList<>();
        person.connect((src, type, payload, at) -> got.add(type));
        feed(frame(SPOT_B, new MovementSummaryReport(2000, new AccelerationSample(0, -1000, 0), 5, 1010)));
        BurstChunk.split(1, 50, 50, java.util.Collections.nCopies(150, new AccelerationSample(0, -1000, 0)))
                .forEach(c -> feed(frame(SPOT_B, c)));
        assertEquals(List.of(6, 6, 6, 6, 6, 6), got, "a summary and the five chunks of a burst");

        feed(SunSpotCodec.encode(SunSpotFrame.of(SPOT_B, new byte[] {6, 0x11, 3, 1}))); // switch 3
        feed(SunSpotCodec.encode(SunSpotFrame.of(SPOT_B, new byte[] {6, 0x31, 1, 0, 1, 50, 0, 0, // x = 16001 mg
                0x3E, (byte) 0x81, 0, 0, 0, 0})));
        feed(SunSpotCodec.encode(SunSpotFrame.of(SPOT_B, new byte[] {6, 0x12, 1, 1}))); // unknown version
        assertEquals(6, got.size(), "refused frames reach no listener");
        assertEquals(2, bus.rejects.count(RejectReason.BAD_VALUE));
        assertEquals(1, bus.rejects.count(RejectReason.UNKNOWN_PAYLOAD));
    }

    @Test
    void aForgottenNodeIsCreatedAnewByItsNextPacket() {
        feed(frame(SPOT_A, new MovementDetection(true)));
        SunSpotBusDevice first = bus.node(SPOT_A);
        bus.nodes.forget(first);
        assertNull(bus.node(SPOT_A));
        feed(frame(SPOT_A, new LightStatus(3)));
        assertNotSame(first, bus.node(SPOT_A));
        assertEquals(first.uid(), bus.node(SPOT_A).uid(), "same address, same UID");
        assertEquals(Set.of("light-sensor"), bus.node(SPOT_A).nodeTypes());
    }

    @Test
    void offlineAffectsOnlyNodesLastHeardOnTheLostLink() {
        bus.feed(frame(SPOT_A, new MovementDetection(true)), "serial /dev/ttyUSB0");
        bus.feed(frame(SPOT_B, new MovementDetection(true)), UDP);
        bus.nodes.offline("serial /dev/ttyUSB0", "serial link lost");
        assertEquals(DeviceStatus.State.OFFLINE, bus.node(SPOT_A).status().state());
        assertEquals(DeviceStatus.State.ONLINE, bus.node(SPOT_B).status().state());
        bus.feed(frame(SPOT_A, new MovementDetection(false)), UDP);
        assertEquals(DeviceStatus.State.ONLINE, bus.node(SPOT_A).status().state());
    }

    @Test
    void twoLinksHearingANewNodeAtOnceCreateOneDevice() throws Exception {
        int threads = 4;
        int perThread = 500;
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        CountDownLatch go = new CountDownLatch(1);
        try {
            for (int t = 0; t < threads; t++) {
                String link = "link-" + t;
                byte[] packet = frame(SPOT_A, t % 2 == 0 ? new MovementDetection(true) : new LightStatus(t));
                pool.execute(() -> {
                    try {
                        go.await();
                    } catch (InterruptedException e) {
                        return;
                    }
                    for (int i = 0; i < perThread; i++) {
                        bus.feed(packet, link);
                    }
                });
            }
            go.countDown();
        } finally {
            pool.shutdown();
            assertTrue(pool.awaitTermination(30, TimeUnit.SECONDS));
        }
        assertEquals(1, bus.nodes.size());
        assertEquals(threads * perThread, bus.node(SPOT_A).packets(), "nothing lost");
        assertEquals(Set.of("movement", "light-sensor"), bus.node(SPOT_A).nodeTypes());
    }
}
