package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.TIMEOUT;
import static org.tinysep.sunspot.busradio.internal.TestBus.await;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Parameter;
import org.tinysep.sunspot.protocol.MovementDetection;

/** One configuration, three links: what runs, what is reported, and that one link's trouble spares the others. */
class SunSpotLinksTest {

    private static final RadiogramSource.Opener NO_SDK = port -> {
        throw new SdkUnavailableException("no javax.microedition.io");
    };

    @AutoClose
    private final TestBus bus = new TestBus();
    private SunSpotLinks links;

    private SunSpotLinks start(LinkSettings settings) {
        links = bus.closing(new SunSpotLinks(settings, NO_SDK, Duration.ofMillis(50), "BusRadioSunSpot"));
        links.bind();
        links.start(bus.handler, bus.nodes, bus.context);
        return links;
    }

    private Map<String, Object> parameters() {
        List<Parameter> list = links.parameters();
        return list.stream().collect(Collectors.toMap(Parameter::key, Parameter::value));
    }

    @Test
    void everyLinkOff() {
        start(new LinkSettings(LinkSettings.UDP_OFF, "127.0.0.1", " ", 115200, false, 100));
        assertEquals("udp: off; serial: off; sdk: off", links.status());
        assertFalse(links.udpPort().isPresent());
        assertTrue(bus.problems().isEmpty(), bus.problems().toString());
    }

    @Test
    void udpRunsWhileTheSdkIsMissing() throws Exception {
        start(new LinkSettings(0, "127.0.0.1", "", 115200, true, 100));
        int port = links.udpPort().orElseThrow();
        await("SDK state", TIMEOUT, () -> links.sdkState().startsWith("Sun SPOT SDK not installed"));
        assertEquals("udp: listening on 127.0.0.1:" + port + "; serial: off; sdk: Sun SPOT SDK not installed "
                + "(no javax.microedition.io)", links.status());
        assertEquals(links.status(), parameters().get("status"));
        await("PROBLEM event", TIMEOUT, () -> bus.problems().stream().anyMatch(p -> p.startsWith("Sun SPOT SDK")));

        byte[] packet = frame(SPOT_A, new MovementDetection(true));
        try (DatagramSocket s = new DatagramSocket()) {
            s.send(new DatagramPacket(packet, packet.length, InetAddress.getLoopbackAddress(), port));
        }
        await("bus device", TIMEOUT, () -> bus.node(SPOT_A) != null && bus.node(SPOT_A).packets() == 1);
    }

    @Test
    void badSettingsAreReportedAndLeaveTheOtherLinksRunning() {
        start(new LinkSettings(70000, "127.0.0.1", "/dev/tinysep-no-such-port", 0, true, 300));
        assertEquals("udp: bad udpPort 70000, expected -1 (off), 0 (a free port) or 1..65535; "
                + "serial: bad serialBaudRate 0; sdk: bad sdkRadiogramPort 300, expected 1..255", links.status());
        assertEquals(3, bus.problems().size(), bus.problems().toString());
        assertTrue(bus.problems().get(0).startsWith("udp: bad udpPort 70000"), bus.problems().get(0));
    }

    @Test
    void aBusyUdpPortIsReportedAndTheSerialLinkStillStarts() throws Exception {
        try (DatagramSocket taken = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            int port = taken.getLocalPort();
            start(new LinkSettings(port, "127.0.0.1", "/dev/tinysep-no-such-port", 115200, false, 100));
            assertTrue(links.udpState().startsWith("cannot listen on 127.0.0.1:" + port), links.udpState());
            assertFalse(links.udpPort().isPresent());
            await("serial retrying", TIMEOUT, () -> links.serialState().startsWith("missing")
                    && links.serialState().contains("no such port"));
            // issue 25, item 7: a caregiver-visible signal (notice, daily summary, WARNING under the banner)
            assertEquals(1, bus.problems().stream().filter(p -> p.startsWith("Monitoring reduced: the Sun SPOT radio "
                    + "cannot listen on 127.0.0.1:" + port) && p.contains("no Sun SPOT sensor is heard")).count(),
                    bus.problems().toString());
        }
    }
}
