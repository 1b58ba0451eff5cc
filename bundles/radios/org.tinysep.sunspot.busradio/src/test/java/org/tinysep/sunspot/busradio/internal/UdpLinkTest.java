package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_B;
import static org.tinysep.sunspot.busradio.internal.TestBus.TIMEOUT;
import static org.tinysep.sunspot.busradio.internal.TestBus.await;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.SocketException;
import java.util.Set;
import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.Test;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** The UDP link with real sockets on 127.0.0.1. */
class UdpLinkTest {

    @AutoClose
    private final TestBus bus = new TestBus();
    private UdpLink link;

    private void send(DatagramSocket from, byte[] bytes) throws IOException {
        from.send(new DatagramPacket(bytes, bytes.length, InetAddress.getLoopbackAddress(), link.socket().localPort()));
    }

    @Test
    void datagramsBecomeBusDevicesAndBadOnesAreCounted() throws Exception {
        link = bus.closing(UdpLink.open("127.0.0.1", 0, "test"));
        assertTrue(link.socket().localPort() > 0);
        assertTrue(link.socket().localAddress().startsWith("127.0.0.1:"), link.socket().localAddress());
        link.start(bus.handler);
        byte[] bad = frame(SPOT_A, new LightStatus(1));
        bad[bad.length - 1] ^= 0x55;
        try (DatagramSocket sender = new DatagramSocket()) {
            send(sender, frame(SPOT_A, new MovementDetection(true)));
            send(sender, frame(SPOT_A, new LightStatus(70)));
            send(sender, bad);
            send(sender, new byte[300]);
            send(sender, frame(SPOT_B, new TemperatureStatus(-3.5)));
            // one receive thread, in order: the last datagram delivered means all were handled
            await("5 datagrams", TIMEOUT, () -> bus.node(SPOT_B) != null && bus.node(SPOT_B).packets() == 1);
            assertEquals(5, bus.handler.received());
            assertEquals(Set.of("movement", "light-sensor"), bus.node(SPOT_A).nodeTypes());
            assertEquals(Set.of("temperature"), bus.node(SPOT_B).nodeTypes());
            assertEquals(1, bus.rejects.count(RejectReason.BAD_CHECKSUM));
            assertEquals(1, bus.rejects.count(RejectReason.OVERSIZE), "a 300-byte datagram is not cut short");
            assertEquals("udp 127.0.0.1:" + sender.getLocalPort(), bus.node(SPOT_B).link());
        }
    }

    @Test
    void nothingIsLostInABurst() throws Exception {
        link = bus.closing(UdpLink.open("127.0.0.1", 0, "test"));
        assertTrue(link.socket().receiveBufferSize() > 0);
        link.start(bus.handler);
        int count = 2000;
        try (DatagramSocket sender = new DatagramSocket()) {
            byte[] packet = frame(SPOT_A, new MovementDetection(true));
            for (int i = 0; i < count; i++) {
                send(sender, packet);
            }
        }
        await(count + " datagrams", TIMEOUT, () -> bus.node(SPOT_A) != null && bus.node(SPOT_A).packets() == count);
        assertEquals(count, bus.handler.received());
    }

    @Test
    void aBusyPortIsAnIoErrorAndCloseEndsTheLoop() throws Exception {
        link = bus.closing(UdpLink.open("127.0.0.1", 0, "test"));
        link.start(bus.handler);
        int port = link.socket().localPort();
        assertThrows(SocketException.class, () -> UdpLink.open("127.0.0.1", port, "second"));
        link.close();
        try (DatagramSocket again = new DatagramSocket(port, InetAddress.getLoopbackAddress())) {
            assertEquals(port, again.getLocalPort(), "close released the port");
        }
    }
}
