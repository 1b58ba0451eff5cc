package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_B;
import static org.tinysep.sunspot.busradio.internal.TestBus.TIMEOUT;
import static org.tinysep.sunspot.busradio.internal.TestBus.await;

import java.time.Duration;
import java.util.Set;
import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** The SDK link through its seam, with an in-process fake radiogram source; and the real opener without an SDK. */
class SdkLinkTest {

    private static final byte[] MOTION = SunSpotPayloads.encode(new MovementDetection(true));

    @AutoClose
    private final TestBus bus = new TestBus();
    private final FakeRadiograms sdk = new FakeRadiograms();
    private SdkLink link;

    private void startLink(RadiogramSource.Opener opener) {
        link = bus.closing(new SdkLink(opener, 100, Duration.ofMillis(20), bus.feed));
        link.start();
    }

    @Test
    void radiogramsTakeTheSharedPathToBusDevices() {
        startLink(sdk);
        await("radiogram port open", TIMEOUT, sdk::isOpen);
        assertEquals(100, sdk.openedPort);
        assertEquals("receiving on sdk radiogram://:100", link.state());

        sdk.send("0014.4F01.0000.1234", MOTION);
        sdk.send("radiogram://0014.4f01.0000.5678:100", SunSpotPayloads.encode(new TemperatureStatus(19.0)));
        await("2 radiograms", TIMEOUT, () -> bus.node(SPOT_B) != null && bus.node(SPOT_B).packets() == 1);

        assertEquals(Set.of("movement"), bus.node(SPOT_A).nodeTypes());
        assertEquals(Set.of("temperature"), bus.node(SPOT_B).nodeTypes(), "scheme, case and port are tolerated");
        assertEquals("sdk radiogram://:100", bus.node(SPOT_A).link());
        assertArrayEquals(MOTION, bus.logs.packets().get(0).bytes(), "the packet log holds what arrived");
        assertEquals("node 0014.4F01.0000.1234 via sdk radiogram://:100", bus.logs.packets().get(0).origin());
    }

    @Test
    void badRadiogramsAreCountedAndNeverStopTheLink() {
        startLink(sdk);
        await("radiogram port open", TIMEOUT, sdk::isOpen);
        sdk.send("0014.4F01.0000.1234", new byte[0]);
        sdk.send("0014.4F01.0000.1234", new byte[300]);
        sdk.send("0014.4F01.0000.1234", new byte[] {9, 1, 0, 1});
        sdk.send("0014.4F01.0000.1234", new byte[] {2, 1, 0, 7});
        sdk.send("not an address", MOTION);
        sdk.send(null, MOTION);
        sdk.send("0014.4F01.0000.1234", MOTION);
        await("the good radiogram", TIMEOUT, () -> bus.node(SPOT_A) != null && bus.node(SPOT_A).packets() == 1);

        assertEquals(2, bus.rejects.count(RejectReason.UNKNOWN_PAYLOAD));
        assertEquals(1, bus.rejects.count(RejectReason.OVERSIZE));
        assertEquals(1, bus.rejects.count(RejectReason.BAD_VALUE));
        assertEquals(2, link.unreadable());
        assertEquals(1, bus.problems().stream().filter(p -> p.contains("unreadable sender address")).count());
        assertEquals(5, bus.handler.received(), "unreadable radiograms never reach the handler");
    }

    @Test
    void aMissingSdkIsReportedAsStatusAndProblem() {
        startLink(port -> {
            throw new SdkUnavailableException("no javax.microedition.io");
        });
        await("SDK state", TIMEOUT, () -> link.state().startsWith("Sun SPOT SDK not installed"));
        assertEquals("Sun SPOT SDK not installed (no javax.microedition.io)", link.state());
        await("PROBLEM event", TIMEOUT, () -> !bus.problems().isEmpty());
        assertTrue(bus.problems().get(0).startsWith("Sun SPOT SDK not installed"), bus.problems().get(0));
    }

    @Test
    void withoutTheSdkTheRealOpenerSaysSdkNotInstalled() {
        // the test class path has only the CLDC API stub jar (org.microemu:cldcapi11), no Sun SPOT SDK
        SdkUnavailableException e = assertThrows(SdkUnavailableException.class, () -> SdkRadiograms.OPENER.open(100));
        assertTrue(e.getMessage().startsWith("Sun SPOT SDK not installed ("), e.getMessage());
    }

    @Test
    void failedOpensAreRetriedAndALostConnectionIsReopened() {
        sdk.failOpens.set(2);
        startLink(sdk);
        await("third open", TIMEOUT, sdk::isOpen);
        assertEquals(3, sdk.opens.get());
        assertEquals(1, bus.problems().stream().filter(p -> p.startsWith("cannot open")).count(),
                "one outage, one PROBLEM: " + bus.problems());

        sdk.send("0014.4F01.0000.1234", MOTION);
        await("first radiogram", TIMEOUT, () -> bus.node(SPOT_A) != null && bus.node(SPOT_A).packets() == 1);
        sdk.breakConnection();
        await("device offline", TIMEOUT,
                () -> bus.node(SPOT_A).status().state() == DeviceStatus.State.OFFLINE);
        await("reopened", TIMEOUT, () -> sdk.opens.get() == 4 && sdk.isOpen());
        sdk.send("0014.4F01.0000.1234", MOTION);
        await("second radiogram", TIMEOUT, () -> bus.node(SPOT_A).packets() == 2);
        assertEquals(DeviceStatus.State.ONLINE, bus.node(SPOT_A).status().state());
    }

    @Test
    void closeEndsABlockedReceive() {
        startLink(sdk);
        await("radiogram port open", TIMEOUT, sdk::isOpen);
        link.close();
        assertFalse(sdk.isOpen());
        assertEquals("closed", link.state());
    }

    @Test
    void bareAddressDropsSchemeAndPort() {
        assertEquals("0014.4F01.0000.1234", SdkLink.bareAddress("radiogram://0014.4F01.0000.1234:100"));
        assertEquals("0014.4F01.0000.1234", SdkLink.bareAddress("0014.4F01.0000.1234"));
        assertNull(SdkLink.bareAddress(null));
    }
}
