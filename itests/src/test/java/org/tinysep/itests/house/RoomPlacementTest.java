package org.tinysep.itests.house;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.TinySepTestSupport;

/**
 * Configured room placement (pid {@value #PLACEMENT_PID}): devices of a node appear in the room a rule names,
 * unless the user placed them first; bad rules are reported once and the rest still applies.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class RoomPlacementTest extends TinySepTestSupport {

    private static final String PLACEMENT_PID = "org.tinysep.houseinformation.placement";

    private static final String HOUSE_PID = "org.tinysep.houseinformation";

    /** The configuration folder is shared by the test methods: each starts on a new, empty house file. */
    private void freshHouse() {
        try {
            Path file = Files.createTempDirectory("tinysep-placement-").resolve("house.xml");
            configure(HOUSE_PID, Map.of("file", file.toString()));
            await(TIMEOUT, () -> houseOn(file), "House Information on " + file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private boolean houseOn(Path file) {
        try {
            ServiceReference<?>[] refs = context.getServiceReferences(Device.class.getName(),
                    "(" + DeviceProperties.DEVICE_TYPE + "=HouseInformation)");
            Device d = refs == null ? null : (Device) context.getService(refs[0]);
            return d != null && d.parameters().stream().anyMatch(p -> p.key().equals("file")
                    && p.value().equals(file.toString()))
                    && context.getServiceReference(HouseInformationProvider.class) != null;
        } catch (org.osgi.framework.InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private String addRoom(String name) {
        HouseInformationProvider house = awaitService(HouseInformationProvider.class, null, TIMEOUT);
        shell("tinysep:room-add \"" + name + "\" " + name.replace(" ", ""));
        return house.rooms().stream().filter(r -> r.name().equals(name)).map(Room::uid).findFirst().orElseThrow();
    }

    /** Opens a tracker of the Device services of {@code address} matching {@code extra}. */
    private ServiceTracker<Device, Device> devicesOf(String address, String extra) throws Exception {
        ServiceTracker<Device, Device> t = new ServiceTracker<>(context, context.createFilter("(&(objectClass="
                + Device.class.getName() + ")(" + DeviceProperties.NODE_ADDRESS + "=" + address + ")" + extra + ")"),
                null);
        t.open();
        return t;
    }

    private static Set<String> types(ServiceTracker<Device, Device> t) {
        ServiceReference<Device>[] refs = t.getServiceReferences();
        return refs == null ? Set.of() : java.util.Arrays.stream(refs)
                .map(r -> String.valueOf(r.getProperty(DeviceProperties.DEVICE_TYPE))).collect(Collectors.toSet());
    }

    private List<String> problems(String containing) {
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        return events.recent(1000).stream().filter(e -> e.kind() == EventKind.PROBLEM)
                .map(EventEntry::message).filter(m -> m.contains(containing)).toList();
    }

    @Test
    public void devicesOfAConfiguredNodeArePlacedAndBadRulesReportedOnce() throws Exception {
        freshHouse();
        String hall = addRoom("Hall");
        configure(PLACEMENT_PID, Map.of("placements", "1.17=Hall\n1.18 Kitchen, 1.19=Garage"));
        int port = udpPortOf("BusRadioAmicaUdp");
        ServiceTracker<Device, Device> garageNode = devicesOf("1.19", "");
        ServiceTracker<Device, Device> inHall = devicesOf("1.17", "(" + DeviceProperties.ROOM + "=" + hall + ")");
        try (AmicaNode n19 = new AmicaNode(1, 19, port, AmicaNodeType.MOVEMENT);
                AmicaNode n17 = new AmicaNode(1, 17, port, AmicaNodeType.MOVEMENT)) {
            n19.keepAlive();
            await(TIMEOUT, () -> garageNode.size() == 2, "the bus and movement devices of 1.19");
            n17.keepAlive(); // placed after the 1.19 attempts: one thread, in order
            await(TIMEOUT, () -> inHall.size() == 2, "both devices of 1.17 in the Hall " + hall);
            assertEquals(Set.of("BusRadioAmicaUdp", "AmicaMovement"), types(inHall));
            for (ServiceReference<Device> r : garageNode.getServiceReferences()) {
                assertEquals(null, r.getProperty(DeviceProperties.ROOM));
            }
            List<String> garage = problems("placement rule '1.19=Garage'");
            assertEquals(garage.toString(), 1, garage.size());
            assertTrue(garage.get(0), garage.get(0).contains("unknown room 'Garage'; known rooms: Hall (" + hall));
            assertEquals(1, problems("placement entry '1.18 Kitchen' has no '='").size());
        } finally {
            garageNode.close();
            inHall.close();
        }
    }

    @Test
    public void aDeviceTheUserPlacedKeepsItsRoomWhenTheConfigurationChanges() throws Exception {
        freshHouse();
        String hall = addRoom("Hall");
        String kitchen = addRoom("Kitchen");
        int port = udpPortOf("BusRadioAmicaUdp");
        ServiceTracker<Device, Device> inHall = devicesOf("1.18", "(" + DeviceProperties.ROOM + "=" + hall + ")");
        try (AmicaNode node = new AmicaNode(1, 18, port, AmicaNodeType.MOVEMENT)) {
            node.keepAlive();
            Device movement = awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=AmicaMovement)("
                    + DeviceProperties.NODE_ADDRESS + "=1.18))", TIMEOUT);
            shell("tinysep:set " + movement.uid() + " room Kitchen");

            configure(PLACEMENT_PID, Map.of("placements", "1.18=Hall")); // applies to present unplaced devices
            await(TIMEOUT, () -> inHall.size() == 1, "the bus device of 1.18 in the Hall");
            assertEquals(Set.of("BusRadioAmicaUdp"), types(inHall));
            ServiceReference<Device> ref = awaitReferenceOf(movement.uid());
            assertEquals("the user's placement is kept", kitchen, ref.getProperty(DeviceProperties.ROOM));
        } finally {
            inHall.close();
        }
    }

    private ServiceReference<Device> awaitReferenceOf(String uid) throws Exception {
        ServiceTracker<Device, Device> t = new ServiceTracker<>(context, context.createFilter("(&(objectClass="
                + Device.class.getName() + ")(" + DeviceProperties.DEVICE_UID + "=" + uid + "))"), null);
        t.open();
        try {
            await(TIMEOUT, () -> t.getServiceReference() != null, "device " + uid);
            return t.getServiceReference();
        } finally {
            t.close();
        }
    }
}
