package org.tinysep.itests.serial;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Driver;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.itests.Topology;
import org.tinysep.testsupport.serial.SocatPair;

/**
 * Bus Radio AmICA (serial) in a real Felix framework on socat pseudo-terminals: a factory configuration per port,
 * frames and garbage written at the node's end, the port killed and recreated under the same path, commands read
 * back at the node's end.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class SerialBusRadioTest extends SerialTestSupport {

    private static final String PID = "org.tinysep.amica.busradio.serial";
    private static final String BUS = "BusRadioAmicaSerial";

    private static final String BUS_17 = BUS + "@1.17";
    private static final String MOVEMENT_17 = "AmicaMovement@1.17";
    /** The serial part of the graph with the movement node: its bus device and AmicaMovement's connection. */
    private static final Set<String> SERIAL_LINES =
            Set.of(BUS_17, MOVEMENT_17 + " <- BusRadioAmicaProvider of " + BUS_17);

    private static final String BUS_DEVICES = "(" + DeviceProperties.DEVICE_TYPE + "=" + BUS + ")";
    private static final String SERIAL_DRIVERS = "(" + DeviceProperties.DRIVER_NAME + "=" + BUS + " *)";

    private final SocatPairs socat = new SocatPairs();
    private final List<Configuration> configurations = new ArrayList<>();

    @After
    public void cleanUp() throws Exception {
        for (Configuration c : configurations) {
            c.delete();
        }
        socat.close();
    }

    /** A factory configuration for one port, as {@code etc/org.tinysep.amica.busradio.serial-<name>.cfg} makes. */
    private Driver configurePort(String name, Path port) throws IOException {
        ConfigurationAdmin admin = awaitService(ConfigurationAdmin.class, null, TIMEOUT);
        Configuration c = admin.getFactoryConfiguration(PID, name, "?");
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("port", port.toString());
        props.put("reopenSeconds", "1");
        c.update(props);
        configurations.add(c);
        Driver driver = awaitService(Driver.class, "(tinysep.serial.port=" + port + ")", TIMEOUT);
        assertEquals(BUS + " " + port, driver.name());
        await(TIMEOUT, () -> parameter(driver, "status").startsWith(port + " open"), "the port to open");
        return driver;
    }

    private Device busDevice(String node) {
        return awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=" + BUS + ")("
                + DeviceProperties.NODE_ADDRESS + "=" + node + "))", TIMEOUT);
    }

    private Set<String> serialLines() {
        return Topology.of(context).stream().filter(l -> l.contains(BUS))
                .collect(Collectors.toCollection(TreeSet::new));
    }

    @Test
    public void framesThroughAPseudoTerminalBuildDevicesSurviveThePortVanishingAndCommandsComeOut() throws Exception {
        SocatPair pair = socat.start();
        Driver driver = configurePort("test", pair.a());
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);

        try (PtyNode node = new PtyNode(pair.b(), 1, 17, AmicaNodeType.MOVEMENT)) {
            node.raw(new byte[] {0x00, 0x13, (byte) 0xA1, 0x37}); // line noise before the first frame
            node.keepAlive();
            Set<String> expected = Set.of(BUS_17, MOVEMENT_17 + " <- BusRadioAmicaProvider of " + BUS_17,
                    "FlatOccupancy <- MovementProvider of " + MOVEMENT_17);
            await(TIMEOUT, () -> Topology.of(context).containsAll(expected), "the movement node's devices");
            assertEquals(SERIAL_LINES, serialLines());

            List<Boolean> heard = listenToMovement();
            node.raw(new byte[] {5, 5, 5}, node.frame(new MotionDetection(true)), new byte[] {(byte) 0xFF});
            await(TIMEOUT, () -> heard.equals(List.of(true)), "the motion between the garbage");
            await(TIMEOUT, () -> parameter(driver, "skippedBytes").equals("7"), "4 + 3 skipped bytes");
            assertEquals("2", parameter(driver, "rejected"));

            BusRadioAmicaProvider bus = awaitService(BusRadioAmicaProvider.class,
                    "(" + DeviceProperties.NODE_ADDRESS + "=1.17)", TIMEOUT);
            bus.send(AmicaPayloads.encode(new LightControl(40)));
            AmicaFrame command = node.receive(4);
            assertEquals("1.17", command.receiver().toString());
            assertArrayEquals(AmicaPayloads.encode(new LightControl(40)), command.payload());
        }
        Device busDevice = busDevice("1.17");
        long beforeOutage = events.recent(1).get(0).sequence();

        pair.kill();
        await(TIMEOUT, () -> busDevice.status().state() == DeviceStatus.State.OFFLINE, "the bus device OFFLINE");
        String status = parameter(driver, "status");
        assertTrue(status, status.matches(Pattern.quote(pair.a().toString()) + " (lost|missing) .*"));
        assertEquals("no device removed", SERIAL_LINES, serialLines());
        List<EventEntry> outage = events.recent(1000).stream().filter(e -> e.sequence() > beforeOutage).toList();
        assertTrue(outage.toString(), outage.stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().startsWith("port " + pair.a() + " unavailable")));
        assertTrue(outage.toString(), outage.stream().noneMatch(e -> e.kind() == EventKind.DEVICE_REMOVED));

        pair.start(); // new pseudo-terminals behind the same link paths
        await(TIMEOUT, () -> parameter(driver, "status").startsWith(pair.a() + " open"), "the port to reopen");
        List<Boolean> heard = listenToMovement();
        long beforeMotion = events.recent(1).get(0).sequence();
        try (PtyNode node = new PtyNode(pair.b(), 1, 17, AmicaNodeType.MOVEMENT)) {
            node.motion(false);
            node.motion(true);
            await(TIMEOUT, () -> heard.equals(List.of(false, true)), "motion reports after the outage");
        }
        await(TIMEOUT, () -> busDevice.status().state() == DeviceStatus.State.ONLINE, "the bus device ONLINE again");
        List<EventEntry> after = events.recent(1000).stream().filter(e -> e.sequence() > beforeMotion).toList();
        assertTrue(after.toString(), after.stream().anyMatch(e -> e.kind() == EventKind.STATUS
                && e.origin().equals(busDevice.uid()) && e.message().contains("ONLINE")));
        assertEquals("the same devices, kept across the outage", SERIAL_LINES, serialLines());
        assertEquals("1", parameter(driver, "outages"));
    }

    private List<Boolean> listenToMovement() {
        MovementProvider movement = awaitService(MovementProvider.class, null, TIMEOUT);
        List<Boolean> heard = new CopyOnWriteArrayList<>();
        movement.connect((src, m) -> heard.add(m.detected()));
        return heard;
    }

    @Test
    public void eachFactoryConfigurationIsOnePortWithItsOwnDriverAndDevices() throws Exception {
        SocatPair kitchen = socat.start();
        SocatPair hall = socat.start();
        Driver one = configurePort("kitchen", kitchen.a());
        Driver two = configurePort("hall", hall.a());
        assertNotEquals(one.uid(), two.uid());
        assertEquals(2, count(Driver.class, SERIAL_DRIVERS));

        try (PtyNode a = new PtyNode(kitchen.b(), 1, 17, AmicaNodeType.MOVEMENT);
                PtyNode b = new PtyNode(hall.b(), 1, 17, AmicaNodeType.MOVEMENT)) {
            a.keepAlive();
            b.keepAlive(); // the same address in another radio cell
            await(TIMEOUT, () -> one.devices().size() == 1 && two.devices().size() == 1, "a bus device per port");
        }
        assertNotEquals(one.devices().get(0).uid(), two.devices().get(0).uid());

        configurations.remove(0).delete(); // removing a port's configuration removes its driver and devices
        await(TIMEOUT, () -> count(Device.class, BUS_DEVICES) == 1 && count(Driver.class, SERIAL_DRIVERS) == 1,
                "only the hall's driver and bus device left");
        assertEquals(two.devices().get(0).uid(), busDevice("1.17").uid());
    }
}
