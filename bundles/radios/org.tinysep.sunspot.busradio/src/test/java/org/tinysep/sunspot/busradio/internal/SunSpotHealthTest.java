package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.T0;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.device.support.health.NodePolicy;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** Sun SPOT sensor health (issue 12.1) and the address cap (issue 14), without a framework. */
class SunSpotHealthTest {

    private final TestBus bus = new TestBus();

    @Test
    void aSilentTemperatureSpotGoesOfflineAfterItsIntervalsAndComesBackWithItsNextPacket() {
        bus.nodes.policy(new NodePolicy(3, 0, 1000));
        bus.feed(frame(SPOT_A, new TemperatureStatus(21.5)), "udp 127.0.0.1:5000");
        SunSpotBusDevice spot = bus.node(SPOT_A);
        spot.realSilenceGuard(java.time.Duration.ZERO); // no real waiting in a unit test (the guard: NodeWatchTest)
        bus.handler.tick(T0.plusSeconds(29)); // temperature every 10 s, 3 missed = 30 s
        assertEquals(DeviceStatus.State.ONLINE, spot.status().state());
        bus.handler.tick(T0.plusSeconds(30));
        assertEquals(DeviceStatus.State.OFFLINE, spot.status().state());
        assertEquals(1, bus.problems().size());
        assertTrue(bus.problems().get(0).startsWith("Sun SPOT 0014.4F01.0000.1234 (Sun SPOT 0014.4F01.0000.1234) has "
                + "not been heard since 2026-11-22 10:00:00 UTC (30 s without a report; it promises one every 10 s"),
                bus.problems().get(0));
        assertFalse(spot.health().online());
        assertNull(spot.health().batteryMillivolts(), "the protocol carries no battery level");
        bus.feed(frame(SPOT_A, new TemperatureStatus(21.0)), "udp 127.0.0.1:5000");
        assertEquals(DeviceStatus.State.ONLINE, spot.status().state());
        assertTrue(spot.health().online());
    }

    @Test
    void addressesBeyondTheCapAreRejectedAndCountedWithOneProblem() {
        bus.nodes.policy(new NodePolicy(30, 0, 3));
        for (int i = 0; i < 2000; i++) {
            SunSpotAddress random = SunSpotAddress.parse(String.format("0014.4F01.%04X.%04X", i / 65536, i % 65536));
            bus.feed(frame(random, new TemperatureStatus(20.0)), "udp 127.0.0.1:5000");
        }
        assertEquals(3, bus.nodes.size());
        assertEquals(1997, bus.nodes.overCap());
        assertEquals(1, bus.problems().size());
        assertTrue(bus.problems().get(0).contains("not created: this bus radio already has 3 nodes, its limit "
                + "(maxNodes = 3)"), bus.problems().get(0));
    }
}
