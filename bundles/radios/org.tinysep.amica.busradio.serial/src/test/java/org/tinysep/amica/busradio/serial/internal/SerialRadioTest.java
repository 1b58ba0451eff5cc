package org.tinysep.amica.busradio.serial.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.serial.internal.Wiring.concat;
import static org.tinysep.amica.busradio.serial.internal.Wiring.frame;
import static org.tinysep.amica.busradio.serial.internal.Wiring.keepAlive;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.amica.busradio.base.AmicaBusDevice;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.RejectReason;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.serial.support.SerialPortLink;
import org.tinysep.testsupport.serial.PtyPeer;
import org.tinysep.testsupport.serial.SocatPair;
import org.tinysep.testsupport.wait.Await;

/**
 * The serial bus radio without the framework, on a real socat pseudo-terminal pair: frames and garbage written at
 * the node's end, commands read there, the port killed and recreated under the same path.
 */
class SerialRadioTest {

    @TempDir
    Path dir;
    private SocatPair pair;
    private SerialRadio radio;
    private final Wiring wiring = new Wiring("BusRadioAmicaSerial test");
    private final Map<String, AmicaBusDevice<SerialPortLink>> created = new ConcurrentHashMap<>();

    @BeforeEach
    void socat() throws Exception {
        pair = new SocatPair(dir).start();
        SerialSettings settings =
                new SerialSettings(pair.a().toString(), 115200, Duration.ofSeconds(1), "p", List.of());
        radio = new SerialRadio(wiring.context, settings, device -> {
            created.put(device.nodeId(), device);
            return device;
        });
        radio.start();
        await(radio::isOpen, "the port to open");
    }

    @AfterEach
    void stop() throws Exception {
        radio.close();
        pair.kill();
    }

    private String parameter(String key) {
        return radio.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }

    @Test
    void framesWithGarbageBetweenThemCreateBusDevicesAndCommandsComeOutAtTheNode() throws Exception {
        List<Boolean> motions = new CopyOnWriteArrayList<>();
        try (PtyPeer node = new PtyPeer(pair.b())) {
            node.write(concat(new byte[] {0x13, 0x37, (byte) 0xA1},
                    frame(1, 17, 0, keepAlive(AmicaNodeType.MOVEMENT)), new byte[] {1, 2, 3, 4, 5},
                    frame(1, 20, 0, keepAlive(AmicaNodeType.DIMMABLE_LIGHT))));
            await(() -> created.keySet().equals(Set.of("1.17", "1.20")), "two bus devices");
            AmicaBusDevice<SerialPortLink> movement = created.get("1.17");
            assertEquals(Set.of("movement"), movement.nodeTypes());
            assertEquals("BusRadioAmicaSerial", movement.type());
            movement.connect((src, payload, at) -> motions.add(payload[3] == 1));

            node.write(concat(new byte[] {(byte) 0xA1, (byte) 0xA1}, frame(1, 17, 1, new MotionDetection(true))));
            await(() -> motions.equals(List.of(true)), "the motion after garbage");
            assertEquals("3", parameter("rejected"), "one rejection per run of garbage, not one per byte");
            assertEquals("2", parameter("rejected.bad_header"));
            assertEquals("1", parameter("rejected.length_mismatch"), "A1 A1 04: a header value, then S != L");
            assertEquals(String.valueOf(3 + 5 + 2), parameter("skippedBytes"));
            assertEquals(pair.a().toString(), movement.parameters().stream()
                    .filter(p -> p.key().equals("remote")).findFirst().orElseThrow().value());

            created.get("1.20").send(AmicaPayloads.encode(new LightControl(40)));
            byte[] command = node.read(12);
            AmicaFrame sent = AmicaCodec.decode(command, 0, command.length);
            assertEquals("1.20", sent.receiver().toString());
            assertEquals(0, sent.source());
            assertArrayEquals(AmicaPayloads.encode(new LightControl(40)), sent.payload());
            await(() -> parameter("sent").equals("1"), "the sent counter");
        }
    }

    @Test
    void aVanishedPortTurnsItsDevicesOfflineAndTheyComeBackWithTheirNextPacket() throws Exception {
        try (PtyPeer node = new PtyPeer(pair.b())) {
            node.write(frame(1, 17, 0, keepAlive(AmicaNodeType.MOVEMENT)));
            await(() -> created.containsKey("1.17"), "the bus device");
        }
        AmicaBusDevice<SerialPortLink> movement = created.get("1.17");
        assertEquals(DeviceStatus.State.ONLINE, movement.status().state());

        pair.kill();
        await(() -> movement.status().state() == DeviceStatus.State.OFFLINE, "the device to go OFFLINE");
        assertTrue(movement.status().detail().startsWith("port " + pair.a() + " unavailable: read failed"),
                movement.status().detail());
        assertTrue(parameter("status").matches(Pattern.quote(pair.a().toString()) + " (lost|missing) \\(.*"), parameter("status"));
        List<String> problems = wiring.events(EventKind.PROBLEM);
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).contains("1 bus device(s) OFFLINE; reopening every 1 s by itself"), problems.get(0));
        movement.send(AmicaPayloads.encode(new LightControl(10))); // dropped, counted, never blocks
        await(() -> parameter("sendFailures").equals("1"), "the dropped command to be counted");

        pair.start();
        await(() -> portEvents().size() == 2, "the port to reopen by itself");
        List<String> status = portEvents();
        assertTrue(radio.isOpen());
        assertTrue(status.get(1).endsWith("open at 115200 baud again; its bus devices come back ONLINE with their "
                + "next packet"), status.get(1));
        assertEquals(DeviceStatus.State.OFFLINE, movement.status().state(), "still OFFLINE until it sends");

        try (PtyPeer node = new PtyPeer(pair.b())) {
            node.write(frame(1, 17, 1, new MotionDetection(true)));
            await(() -> movement.status().state() == DeviceStatus.State.ONLINE, "ONLINE with the next packet");
        }
        assertEquals(1, created.size(), "the same device, kept across the outage");
        assertEquals("1", parameter("outages"));
        assertEquals(0, Long.parseLong(parameter("rejected.unknown_node")));
    }

    @Test
    void aFrameCutByTheOutageIsCountedAsTruncatedAndDoesNotSpoilTheNextOne() throws Exception {
        byte[] keepAlive = frame(1, 17, 0, keepAlive(AmicaNodeType.MOVEMENT));
        try (PtyPeer node = new PtyPeer(pair.b())) {
            node.write(Arrays.copyOf(keepAlive, 9));
            await(() -> Long.parseLong(parameter("bytesReceived")) == 9, "the partial frame to arrive");
        }
        pair.kill();
        await(() -> !radio.isOpen(), "the port to be lost");
        pair.start();
        await(radio::isOpen, "the port to reopen");
        try (PtyPeer node = new PtyPeer(pair.b())) {
            node.write(keepAlive);
            await(() -> created.containsKey("1.17"), "the bus device from the complete frame");
        }
        assertEquals("1", parameter("rejected." + RejectReason.TRUNCATED.name().toLowerCase()));
    }

    private List<String> portEvents() {
        return wiring.events(EventKind.STATUS).stream().filter(m -> m.startsWith("port ")).toList();
    }

    static void await(BooleanSupplier condition, String what) throws InterruptedException {
        Await.until(condition, what);
    }
}
