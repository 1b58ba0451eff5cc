package org.tinysep.itests.house;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.TinySepTestSupport;

/**
 * docs/acceptance.md scenario 4 (thesis Fig 3.8): House Information's device exists at once; the house is edited through
 * the shell, listeners hear every change, and a real AmICA movement device is placed in a room so consumers can
 * filter on {@code tinysep.room}. The house file lives in a fresh temp folder per framework.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class HouseInformationTest extends TinySepTestSupport {

    private static final String HOUSE_PID = "org.tinysep.houseinformation";
    private static final String HOUSE_FILTER = "(" + DeviceProperties.DEVICE_TYPE + "=HouseInformation)";

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        try {
            Path dir = Files.createTempDirectory("tinysep-house-");
            configs.put(HOUSE_PID, Map.of("file", dir.resolve("house.xml").toString()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return configs;
    }

    /** @return the House Information device registered now (services change when the configuration does) */
    private Device houseDevice() {
        try {
            ServiceReference<?>[] refs = context.getServiceReferences(Device.class.getName(), HOUSE_FILTER);
            return refs == null ? null : (Device) context.getService(refs[0]);
        } catch (org.osgi.framework.InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * Points House Information at a new, empty temp folder (the framework may be shared by the test methods'
     * configuration folder) and waits for the device to be recreated on it.
     */
    private HouseInformationProvider freshHouse() throws IOException {
        Path file = Files.createTempDirectory("tinysep-house-").resolve("house.xml");
        configure(HOUSE_PID, Map.of("file", file.toString()));
        await(TIMEOUT, () -> {
            Device d = houseDevice();
            return d != null && parameter(d, "file").equals(file.toString());
        }, "House Information on " + file);
        HouseInformationProvider house = awaitService(HouseInformationProvider.class, null, TIMEOUT);
        assertEquals(List.of(), house.rooms());
        return house;
    }

    private Path houseFile(Device house) {
        return Path.of(parameter(house, "file"));
    }

    private static String parameter(Device d, String key) {
        return d.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError("no parameter " + key + " in " + d.parameters()));
    }

    private String shellFails(String line) {
        try {
            shell(line);
        } catch (AssertionError expected) {
            return expected.getMessage();
        }
        fail("'" + line + "' should have failed");
        return null;
    }

    @Test
    public void theHouseDeviceExistsAtOnceWithoutAnyHardware() throws Exception {
        Device house = awaitService(Device.class, HOUSE_FILTER, TIMEOUT);
        HouseInformationProvider provider = awaitService(HouseInformationProvider.class, null, TIMEOUT);
        assertEquals(house.uid(), provider.deviceUid());
        assertEquals(DeviceStatus.State.ONLINE, house.status().state());
        assertTrue("configured through initialConfigurations(): " + houseFile(house),
                houseFile(house).toString().contains("tinysep-house-"));
        provider = freshHouse();
        assertEquals(List.of(), provider.rooms());
        assertFalse("no file = empty house, nothing written yet", Files.exists(houseFile(houseDevice())));
        Bundle jaxbUser = org.osgi.framework.FrameworkUtil.getBundle(provider.getClass());
        assertEquals(Bundle.ACTIVE, jaxbUser.getState());
    }

    @Test
    public void shellCommandsEditTheHouseAndListenersHearEachChange() throws Exception {
        HouseInformationProvider provider = freshHouse();
        Device house = houseDevice();
        List<List<Room>> heard = new CopyOnWriteArrayList<>();
        provider.connect((source, rooms, at) -> heard.add(rooms));

        assertTrue(shell("tinysep:room-add Bathroom Bathroom").contains("added Bathroom ("));
        shell("tinysep:room-add \"Master Bedroom\" Bedroom");
        shell("tinysep:room-add Kitchen Kitchen");
        assertEquals(3, heard.size());
        shell("tinysep:room-link bathroom \"master bedroom\"");
        String bath = provider.rooms().get(0).uid();
        shell("tinysep:room-link " + provider.rooms().get(2).uid().substring(0, 8) + " \"Master Bedroom\"");
        Room bedroom = provider.rooms().get(1);
        assertEquals(2, bedroom.neighbours().size());
        assertTrue(provider.room(bath).orElseThrow().neighbours().contains(bedroom.uid()));
        shell("tinysep:room-rename Kitchen Cuisine");
        String rooms = shell("tinysep:rooms");
        assertTrue(rooms, rooms.lines().anyMatch(l -> l.startsWith(bedroom.uid()) && l.contains("Bathroom, Cuisine")));
        shell("tinysep:room-unlink cuisine \"Master Bedroom\"");
        shell("tinysep:room-remove Bathroom");
        assertEquals(List.of("Master Bedroom", "Cuisine"), provider.rooms().stream().map(Room::name).toList());
        assertEquals(List.of(), provider.rooms().get(0).neighbours().stream().toList());
        assertEquals("each change heard once", 8, heard.size());
        assertEquals(provider.rooms(), heard.get(7));

        String xml = Files.readString(houseFile(house));
        assertTrue(xml, xml.contains("<HOUSE_ROOMS>") && xml.contains("<NAME>Cuisine</NAME>"));
        assertTrue(Files.exists(Path.of(houseFile(house) + ".bak")));

        assertTrue(shellFails("tinysep:room-link Garage Cuisine").contains("unknown room 'Garage'"));
        assertTrue(shellFails("tinysep:room-add \" \" Hall").contains("room name must not be blank"));
        assertTrue(shellFails("tinysep:room-remove").contains("usage: room-remove <room>"));
        assertEquals(8, heard.size());
    }

    /** Gogo's own help left out the Function services (rooms, room-*): TinySEP's help lists them (issue 32 item 6). */
    @Test
    public void helpListsEveryCommandTheRoomCommandsToo() {
        String help = shell("help");
        for (String c : List.of("tinysep:rooms", "tinysep:room-add", "tinysep:room-remove", "tinysep:room-link",
                "tinysep:devices", "tinysep:drivers", "tinysep:events", "tinysep:backup", "felix:lb")) {
            assertTrue(c + " missing from help:\n" + help, help.lines().anyMatch(l -> l.strip().equals(c)));
        }
        String one = shell("help tinysep:devices");
        assertTrue(one, one.contains("lists the devices a filter names"));
    }

    @Test
    public void aMovementDevicePlacedInTheBathroomIsFoundByItsRoom() throws Exception {
        HouseInformationProvider provider = freshHouse();
        shell("tinysep:room-add Bathroom Bathroom");
        String bath = provider.rooms().get(0).uid();
        int port = udpPortOf("BusRadioAmicaUdp");
        try (AmicaNode node = new AmicaNode(1, 17, port, AmicaNodeType.MOVEMENT)) {
            node.keepAlive();
            Device movement = awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=AmicaMovement)("
                    + DeviceProperties.NODE_ADDRESS + "=1.17))", TIMEOUT);
            assertEquals("", parameter(movement, "room"));

            String reply = shellFails("tinysep:set " + movement.uid() + " room Garage");
            assertTrue(reply, reply.contains("unknown room 'Garage'; known rooms: Bathroom (" + bath + ")"));

            shell("tinysep:set " + movement.uid() + " room Bathroom");
            assertEquals("Bathroom (" + bath + ")", parameter(movement, "room"));
            ServiceTracker<MovementProvider, MovementProvider> inBathroom = new ServiceTracker<>(context,
                    context.createFilter("(&(objectClass=" + MovementProvider.class.getName() + ")("
                            + DeviceProperties.ROOM + "=" + bath + "))"), null);
            inBathroom.open();
            try {
                MovementProvider found = inBathroom.waitForService(TIMEOUT.toMillis());
                assertNotNull("a MovementProvider in the bathroom", found);
                assertEquals(movement.uid(), found.deviceUid());
                String rooms = shell("tinysep:rooms");
                assertTrue(rooms, rooms.lines().anyMatch(l -> l.startsWith(bath) && l.endsWith(movement.name())));

                shell("tinysep:room-remove Bathroom");
                await(TIMEOUT, () -> inBathroom.getServiceReferences() == null, "the device to leave the removed room");
                ServiceReference<?>[] refs = context.getServiceReferences(Device.class.getName(),
                        "(" + DeviceProperties.DEVICE_UID + "=" + movement.uid() + ")");
                assertNull(refs[0].getProperty(DeviceProperties.ROOM));
                assertEquals("", parameter(movement, "room"));
            } finally {
                inBathroom.close();
            }
        }
    }

    @Test
    public void aMalformedFileIsReportedMovedAsideAndTheLastGoodHouseKept() throws Exception {
        HouseInformationProvider first = freshHouse();
        first.addRoom("Hall", "Hall");
        first.addRoom("Kitchen", "Kitchen"); // house.xml.bak now holds the Hall only
        Path file = houseFile(houseDevice());
        Path copy = Files.createTempDirectory("tinysep-house-").resolve("house.xml");
        Files.copy(Path.of(file + ".bak"), Path.of(copy + ".bak"));
        Files.writeString(copy, "<HOUSE_ROOMS>\n<ROOM>\n<UID>x</UID>\n</ROOM\n</HOUSE_ROOMS>");

        configure(HOUSE_PID, Map.of("file", copy.toString()));
        await(TIMEOUT, () -> {
            Device d = houseDevice();
            return d != null && parameter(d, "file").equals(copy.toString());
        }, "House Information on " + copy);
        Device house = houseDevice();
        assertEquals(DeviceStatus.State.ERROR, house.status().state());
        String detail = house.status().detail();
        assertTrue(detail, detail.startsWith(copy + " at line 5, column 1: bad XML: "));
        assertTrue(detail, detail.contains("using the last good house from house.xml.bak (1 rooms)"));
        HouseInformationProvider provider = awaitService(HouseInformationProvider.class, null, TIMEOUT);
        assertEquals(List.of("Hall"), provider.rooms().stream().map(Room::name).toList());
        try (var files = Files.list(copy.getParent())) {
            assertEquals(1, files.filter(f -> f.getFileName().toString().startsWith("house.xml.broken-")).count());
        }
        String log = shell("tinysep:log 50");
        assertTrue(log, log.contains("PROBLEM"));
    }

}
