package org.tinysep.itests.continuity;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.TestSyncKey;
import org.tinysep.itests.TinySepTestSupport;

/**
 * Issue 10 item 1 with the real bundles: the clock is driven a day ahead (EXTERNAL, as the demo does), a person
 * moves in the bathroom, then the clock goes back to real time through ConfigAdmin ({@code tinysep:time real}
 * does the same). The quiet time must be counted on the real clock at once and a fresh movement must count — it
 * was ignored as "older than the last activity" and the deadline stayed a day ahead.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class ClockJumpTest extends TinySepTestSupport {

    private static final Map<String, String> EXTERNAL = TestSyncKey.timeConfig("EXTERNAL");

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        configs.put("org.tinysep.timecontroller", EXTERNAL);
        configs.put("org.tinysep.inactivity", Map.of("timeZone", "UTC"));
        try {
            configs.put("org.tinysep.houseinformation", Map.of("file",
                    Files.createTempDirectory("tinysep-continuity-house-").resolve("house.xml").toString()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return configs;
    }

    @Test
    public void timeJumpForwardsThenBackNeverIgnoresFreshActivity() throws Exception {
        try (AmicaNode bath = new AmicaNode(1, 40, udpPortOf("BusRadioAmicaUdp"), MOVEMENT)) {
            TimeControllerProvider clock = awaitService(TimeControllerProvider.class, null, TIMEOUT);
            Instant future = clock.now().truncatedTo(ChronoUnit.SECONDS).plus(Duration.ofDays(1));
            tick(future);
            shell("tinysep:room-add Bathroom Bathroom");
            placeInBathroom(bath);
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            Device device = awaitService(Device.class, "(" + DeviceProperties.DEVICE_UID + "="
                    + inactivity.deviceUid() + ")", TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            bath.motion(true);
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
            await(TIMEOUT, () -> parameter(device, "lastActivity").contains("in Bathroom"), "the bathroom activity");
            assertEquals(future.plus(Duration.ofMinutes(45)).toString(), parameter(device, "deadline"));
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());

            configure("org.tinysep.timecontroller", TestSyncKey.timeConfig("REAL")); // what tinysep:time real does
            await(TIMEOUT, () -> clock.mode() == ClockMode.REAL, "the clock back in real time");
            Instant realLimit = Instant.now().plus(Duration.ofMinutes(46));
            await(TIMEOUT, () -> Instant.parse(parameter(device, "deadline")).isBefore(realLimit),
                    "the quiet time counted on the real clock (deadline now " + parameter(device, "deadline") + ")");

            Instant before = Instant.now();
            bath.motion(true);
            await(TIMEOUT, () -> !Instant.parse(parameter(device, "deadline")).isBefore(
                    before.plus(Duration.ofMinutes(45))), "the fresh movement counted (deadline "
                    + parameter(device, "deadline") + ", last activity " + parameter(device, "lastActivity") + ")");
            assertTrue(Instant.parse(parameter(device, "deadline")).isBefore(realLimit));
            String events = shell("tinysep:log 300");
            assertTrue(events, events.contains("clock went back from "));
            assertTrue(events, events.contains("quiet time in Bathroom counted from now"));
            assertEquals(InactivityState.WATCHING, inactivity.state());
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());
        }
    }

    /**
     * The one place that speaks the time synchroniser's protocol ({@code docs/time-sync.md}): {@code HELLO} for the
     * session, then {@code TICK <seq> <at> <hmac>} signed with the tests' key, answered {@code DONE <seq> <at>}.
     */
    private void tick(Instant at) throws IOException {
        String filter = "(&(" + DeviceProperties.DRIVER_NAME + "=TimeController)(tinysep.sync.port=*))";
        awaitService(Driver.class, filter, TIMEOUT);
        ServiceReference<?> ref;
        try {
            ref = context.getServiceReferences(Driver.class.getName(), filter)[0];
        } catch (org.osgi.framework.InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        int port = ((Number) ref.getProperty("tinysep.sync.port")).intValue();
        try (DatagramSocket socket = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            socket.setSoTimeout(5000);
            InetSocketAddress platform = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
            String[] welcome = ask(socket, platform, "HELLO").split(" ");
            assertEquals("WELCOME <instant> <mode> <session>", 4, welcome.length);
            assertEquals("DONE 1 " + at, ask(socket, platform, TestSyncKey.signed(welcome[3], "TICK 1 " + at)));
        }
    }

    private static String ask(DatagramSocket socket, InetSocketAddress platform, String request) throws IOException {
        byte[] out = request.getBytes(StandardCharsets.US_ASCII);
        socket.send(new DatagramPacket(out, out.length, platform));
        byte[] in = new byte[512];
        DatagramPacket answer = new DatagramPacket(in, in.length);
        socket.receive(answer);
        return new String(in, 0, answer.getLength(), StandardCharsets.US_ASCII);
    }

    private void placeInBathroom(AmicaNode node) throws IOException {
        node.keepAlive();
        Device d = awaitService(Device.class, "(&(" + DeviceProperties.DEVICE_TYPE + "=AmicaMovement)("
                + DeviceProperties.NODE_ADDRESS + "=" + node.id() + "))", TIMEOUT);
        await(TIMEOUT, () -> !d.connections().isEmpty(), d.name() + " fully registered");
        await(TIMEOUT, () -> {
            try {
                shell("tinysep:set " + d.uid() + " room Bathroom");
                return true;
            } catch (AssertionError e) {
                return false; // the device manager's inventory may lag the Device service by a moment
            }
        }, "placed in the bathroom");
        await(TIMEOUT, () -> parameter(d, "room").equals("Bathroom") || !parameter(d, "room").isBlank(),
                d.name() + " placed");
    }

    private static String parameter(Device device, String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value)
                .map(String::valueOf).findFirst().orElseThrow(() -> new AssertionError(device + " has no " + key));
    }
}
