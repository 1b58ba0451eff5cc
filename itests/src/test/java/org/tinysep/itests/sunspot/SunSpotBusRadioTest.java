package org.tinysep.itests.sunspot;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Collectors;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.osgi.util.tracker.ServiceTrackerCustomizer;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.PacketLog;
import org.tinysep.itests.sunspotabs.SunSpotTestSupport;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * Bus Radio Sun SPOT in a real framework, fed real frames over UDP on 127.0.0.1: a bus device per address appears
 * on the first packet of any kind, its node types accumulate in the service properties (so filters on
 * {@code tinysep.node.type} pick it up later), bad frames are counted per reason, nothing valid is lost, and the
 * missing Sun SPOT SDK is reported without stopping the UDP link.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class SunSpotBusRadioTest extends SunSpotTestSupport {

    private static final String BUS = SUN_SPOT_BUS;

    /** UDP on a free port; the SDK link on, although no SDK is installed: it must say so and harm nothing. */
    @Override
    protected Map<String, String> sunSpotConfiguration() {
        return Map.of("udpPort", "0", "udpBindAddress", "127.0.0.1", "sdkEnabled", "true");
    }

    private BusRadioSunSpotProvider busDevice(String address) {
        return awaitService(BusRadioSunSpotProvider.class, "(" + DeviceProperties.NODE_ADDRESS + "=" + address + ")",
                TIMEOUT);
    }

    /** @return the bus device's {@code tinysep.node.type} service property, as a set */
    private Set<String> nodeTypeProperty(String address) throws InvalidSyntaxException {
        Collection<ServiceReference<BusRadioSunSpotProvider>> refs = context.getServiceReferences(
                BusRadioSunSpotProvider.class, "(" + DeviceProperties.NODE_ADDRESS + "=" + address + ")");
        assertEquals("one bus device per address", 1, refs.size());
        Object types = refs.iterator().next().getProperty(DeviceProperties.NODE_TYPE);
        return types instanceof String[] a ? new TreeSet<>(Arrays.asList(a)) : Set.of();
    }

    /** Waits until the bus device of {@code address} has delivered {@code packets} packets (its parameter). */
    private void awaitDelivered(String address, int packets) {
        Device device = awaitService(Device.class, "(&(" + DeviceProperties.NODE_ADDRESS + "=" + address + ")("
                + DeviceProperties.DRIVER_NAME + "=" + BUS + "))", TIMEOUT);
        await(TIMEOUT, () -> device.parameters().stream().anyMatch(p -> p.key().equals("packets")
                && p.value().equals(String.valueOf(packets))), address + " to deliver " + packets + " packets");
    }

    private Map<String, String> driverParameters() {
        Driver driver = awaitService(Driver.class, "(" + DeviceProperties.DRIVER_NAME + "=" + BUS + ")", TIMEOUT);
        return driver.parameters().stream().collect(Collectors.toMap(Parameter::key, Parameter::value));
    }

    @Test
    public void firstPacketCreatesTheBusDeviceAndNodeTypesAccumulate() throws Exception {
        String spot = "0014.4F01.0000.0A01";
        // a consumer interested in light sensors only, filtering like an abstraction driver does
        AtomicInteger lightSensorsSeen = new AtomicInteger();
        String lightFilter = "(&(objectClass=" + BusRadioSunSpotProvider.class.getName() + ")("
                + DeviceProperties.NODE_ADDRESS + "=" + spot + ")(" + DeviceProperties.NODE_TYPE + "=light-sensor))";
        ServiceTracker<Object, Object> lights = new ServiceTracker<>(context, context.createFilter(lightFilter),
                new ServiceTrackerCustomizer<>() {
                    @Override
                    public Object addingService(ServiceReference<Object> reference) {
                        lightSensorsSeen.incrementAndGet();
                        return reference;
                    }

                    @Override
                    public void modifiedService(ServiceReference<Object> reference, Object service) {
                    }

                    @Override
                    public void removedService(ServiceReference<Object> reference, Object service) {
                    }
                });
        lights.open();
        try (SunSpotSender sender = new SunSpotSender(udpPortOf(BUS))) {
            sender.send(spot, new TemperatureStatus(21.5));
            BusRadioSunSpotProvider device = busDevice(spot);
            awaitDelivered(spot, 1);
            assertEquals(spot, device.nodeAddress());
            assertEquals(Set.of("temperature"), device.nodeTypes());
            assertEquals(Set.of("temperature"), nodeTypeProperty(spot));
            assertEquals("not a light sensor yet", 0, lightSensorsSeen.get());

            List<String> heard = new CopyOnWriteArrayList<>();
            Connection c = device.connect((src, type, payload, at) -> heard.add(type + ":" + payload.length));
            sender.send(spot, new LightStatus(64));
            await(TIMEOUT, () -> lightSensorsSeen.get() == 1, "the light-sensor filter to match the same device");
            sender.send(spot, new MovementDetection(true, new Position(120, -40, 0)));
            await(TIMEOUT, () -> heard.size() == 2, "2 payloads delivered");
            assertEquals(List.of("4:4", "2:10"), heard);
            assertEquals(Set.of("light-sensor", "movement", "temperature"), nodeTypeProperty(spot));
            assertEquals(Set.of("light-sensor", "movement", "temperature"), device.nodeTypes());
            c.close();
        } finally {
            lights.close();
        }
    }

    /**
     * Removing a bus device forgets its node (the device leaves the node table as it is disposed, issue 16): the
     * node's next packet creates it anew, under the same UID, counting its packets from 1 again.
     */
    @Test
    public void aRemovedBusDeviceIsCreatedAnewByTheNodesNextPacket() throws Exception {
        String spot = "0014.4F01.0000.0E01";
        String filter = "(&(" + DeviceProperties.NODE_ADDRESS + "=" + spot + ")(" + DeviceProperties.DRIVER_NAME
                + "=" + BUS + "))";
        try (SunSpotSender sender = new SunSpotSender(udpPortOf(BUS))) {
            sender.send(spot, new TemperatureStatus(20.0));
            sender.send(spot, new TemperatureStatus(20.5));
            awaitDelivered(spot, 2);
            String uid = awaitService(Device.class, filter, TIMEOUT).uid();
            Driver driver = awaitService(Driver.class, "(" + DeviceProperties.DRIVER_NAME + "=" + BUS + ")", TIMEOUT);
            assertTrue(driver.removeDevice(uid));
            await(TIMEOUT, () -> {
                try {
                    return context.getServiceReferences(Device.class, filter).isEmpty();
                } catch (InvalidSyntaxException e) {
                    throw new IllegalStateException(e);
                }
            }, "the removed bus device's service to go");

            sender.send(spot, new TemperatureStatus(21.0));
            awaitDelivered(spot, 1);
            assertEquals("the same node, the same UID", uid, awaitService(Device.class, filter, TIMEOUT).uid());
        }
    }

    @Test
    public void badFramesAreCountedPerReasonAndNoValidPacketIsLost() throws Exception {
        String[] spots = {"0014.4F01.0000.0B01", "0014.4F01.0000.0B02", "0014.4F01.0000.0B03"};
        Map<String, String> before = driverParameters();
        long rejectedBefore = Long.parseLong(before.get("rejected"));
        try (SunSpotSender sender = new SunSpotSender(udpPortOf(BUS))) {
            for (String spot : spots) {
                sender.send(spot, new PetMovementDetection(false)); // creates the bus device
            }
            List<byte[]> heard = new CopyOnWriteArrayList<>();
            List<Connection> connections = new ArrayList<>();
            for (String spot : spots) {
                awaitDelivered(spot, 1);
                connections.add(busDevice(spot).connect((src, type, payload, at) -> heard.add(payload)));
            }
            byte[] good = SunSpotCodec.encode(SunSpotFrame.of(SunSpotAddress.parse(spots[0]),
                    SunSpotPayloads.encode(new PetMovementDetection(true))));
            byte[] badChecksum = good.clone();
            badChecksum[10] ^= 0x21;
            byte[] wrongType = SunSpotCodec.encode(new SunSpotFrame(SunSpotAddress.parse(spots[1]), 3,
                    SunSpotPayloads.encode(new PetMovementDetection(true))));
            byte[] badValue = SunSpotCodec.encode(SunSpotFrame.of(SunSpotAddress.parse(spots[2]),
                    new byte[] {3, 1, 0x7F, 0x7F}));
            int valid = 0;
            for (int round = 0; round < 100; round++) {
                sender.raw(badChecksum);
                sender.raw(Arrays.copyOf(good, 13)); // truncated
                sender.raw(wrongType);
                sender.raw(badValue);
                sender.raw(new byte[400]); // oversize
                sender.send(spots[round % 3], new PetMovementDetection(round % 2 == 0));
                valid++;
            }
            int expectedValid = valid;
            await(TIMEOUT, () -> heard.size() == expectedValid, expectedValid + " valid payloads delivered");
            await(TIMEOUT, () -> Long.parseLong(driverParameters().get("rejected")) == rejectedBefore + 500,
                    "500 rejections counted");
            Map<String, String> after = driverParameters();
            for (String reason : List.of("bad_checksum", "truncated", "type_mismatch", "bad_value", "oversize")) {
                assertEquals(reason, Long.parseLong(before.get("rejected." + reason)) + 100,
                        Long.parseLong(after.get("rejected." + reason)));
            }
            assertArrayEquals(SunSpotPayloads.encode(new PetMovementDetection(false)), heard.get(heard.size() - 1));
            for (String spot : spots) {
                assertEquals(Set.of("pet-collar"), busDevice(spot).nodeTypes());
            }
            connections.forEach(Connection::close);

            PacketLog packets = awaitService(PacketLog.class, null, TIMEOUT);
            assertTrue("rejected packets are in the packet log with their reason", packets.recent(1000).stream()
                    .anyMatch(p -> p.note().startsWith("TYPE_MISMATCH")));
            EventLog events = awaitService(EventLog.class, null, TIMEOUT);
            long typeMismatchProblems = events.recent(10_000).stream().filter(e -> e.kind() == EventKind.PROBLEM)
                    .filter(e -> e.message().contains("TYPE_MISMATCH")).count();
            assertEquals("only the first rejection of a reason is logged", 1, typeMismatchProblems);
        }
    }

    @Test
    public void aMissingSdkIsTheDriversStatusAndTheUdpLinkRunsOn() throws Exception {
        await(TIMEOUT, () -> driverParameters().get("sdk").startsWith("Sun SPOT SDK not installed"),
                "the SDK link to report the missing SDK");
        Map<String, String> params = driverParameters();
        assertTrue(params.get("status"), params.get("status").startsWith("udp: listening on 127.0.0.1:"));
        assertTrue(params.get("status"), params.get("status").contains("sdk: Sun SPOT SDK not installed"));
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        assertTrue(events.recent(10_000).stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().startsWith("Sun SPOT SDK not installed")));
        assertTrue(shell("tinysep:drivers").contains("Sun SPOT SDK not installed"));

        String spot = "0014.4F01.0000.0C01";
        try (SunSpotSender sender = new SunSpotSender(udpPortOf(BUS))) {
            sender.send(spot, new MovementDetection(true));
            assertEquals(Set.of("movement"), busDevice(spot).nodeTypes());
        }
        Map<String, String> counts = driverParameters();
        assertTrue(counts.toString(), Long.parseLong(counts.get("nodes")) >= 1);
    }
}
