package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_B;
import static org.tinysep.sunspot.busradio.internal.TestBus.await;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.io.ByteArrayOutputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Set;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.testsupport.serial.SocatPair;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** The serial link on a socat pseudo-terminal pair: the basestation end writes framed packets. */
class SerialLinkTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(15);

    @TempDir
    Path dir;

    private final TestBus bus = new TestBus();
    private SocatPair socat;
    private SerialLink link;

    @AfterEach
    void close() throws InterruptedException {
        if (link != null) {
            link.close();
        }
        if (socat != null) {
            socat.close();
        }
    }

    private static void write(Path basestation, byte[]... chunks) throws IOException {
        try (FileOutputStream out = new FileOutputStream(basestation.toFile())) {
            for (byte[] c : chunks) {
                out.write(c);
                out.flush();
            }
        }
    }

    private void startLink() {
        link = new SerialLink(socat.a().toString(), 115200, Duration.ofMillis(100), bus.feed);
        link.start();
        await("port open", TIMEOUT, () -> link.state().startsWith("open at"));
    }

    @Test
    void framesInTheStreamBecomeBusDevicesAndGarbageIsCounted() throws Exception {
        socat = new SocatPair(dir).start();
        startLink();
        assertEquals("open at 115200 baud", link.state());

        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        stream.writeBytes(new byte[] {(byte) 0xFF, 0x13, 0x37});
        stream.writeBytes(frame(SPOT_A, new MovementDetection(true)));
        stream.writeBytes(frame(SPOT_A, new LightStatus(33)));
        stream.writeBytes(frame(SPOT_B, new TemperatureStatus(24.4)));
        byte[] all = stream.toByteArray();
        // split across writes in the middle of a frame: the decoder buffers across reads
        write(socat.b(), java.util.Arrays.copyOf(all, 20), java.util.Arrays.copyOfRange(all, 20, all.length));

        await("3 frames", TIMEOUT, () -> bus.node(SPOT_B) != null && bus.node(SPOT_B).packets() == 1);
        assertEquals(3, bus.handler.received());
        assertEquals(Set.of("movement", "light-sensor"), bus.node(SPOT_A).nodeTypes());
        assertEquals(Set.of("temperature"), bus.node(SPOT_B).nodeTypes());
        assertEquals("serial " + socat.a(), bus.node(SPOT_A).link());
        assertEquals(1, bus.rejects.total(), "the 3 garbage bytes are one skipped run");
        assertEquals(1, bus.rejects.count(RejectReason.LENGTH_MISMATCH));
        assertTrue(bus.logs.packets().get(0).note().contains("3 bytes skipped in the serial stream"),
                bus.logs.packets().get(0).note());
        assertEquals(all.length, link.bytesRead());
    }

    @Test
    void aLostPortTakesItsNodesOfflineAndTheLinkReopensByItself() throws Exception {
        socat = new SocatPair(dir).start();
        startLink();
        write(socat.b(), frame(SPOT_A, new PetMovementDetection(true)));
        await("first frame", TIMEOUT, () -> bus.node(SPOT_A) != null && bus.node(SPOT_A).packets() == 1);

        socat.kill();
        await("device offline", TIMEOUT, () -> bus.node(SPOT_A).status().state() == DeviceStatus.State.OFFLINE);
        // the link takes the nodes offline first and then logs the problem: poll for that too
        await("problem event", TIMEOUT,
                () -> bus.problems().stream().anyMatch(p -> p.startsWith("serial " + socat.a())));

        socat.start();
        await("port reopened", TIMEOUT, () -> link.state().startsWith("open at"));
        write(socat.b(), frame(SPOT_A, new PetMovementDetection(false)));
        await("second frame", TIMEOUT, () -> bus.node(SPOT_A).packets() == 2);
        assertEquals(DeviceStatus.State.ONLINE, bus.node(SPOT_A).status().state());
    }

    @Test
    void aMissingPortIsRetriedUntilItAppears() throws Exception {
        socat = new SocatPair(dir);
        startLinkWithoutWaiting();
        await("missing state", TIMEOUT, () -> link.state().startsWith("missing"));
        socat.start();
        await("port open", TIMEOUT, () -> link.state().startsWith("open at"));
        write(socat.b(), frame(SPOT_B, new LightStatus(100)));
        await("frame", TIMEOUT, () -> bus.node(SPOT_B) != null && bus.node(SPOT_B).packets() == 1);
    }

    private void startLinkWithoutWaiting() {
        link = new SerialLink(socat.a().toString(), 115200, Duration.ofMillis(100), bus.feed);
        link.start();
    }
}
