package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Issue 14: the drop count of a Java socket on 127.0.0.1 (listed in /proc/net/udp6: dual-stack) is seen. */
class KernelDropsTest {

    @Test
    void dropsAtAFullJavaSocketOnLoopbackAreCounted() throws Exception {
        assumeTrue(Files.isReadable(Path.of("/proc/net/udp6")), "Linux with IPv6 tables only");
        try (DatagramSocket receiver = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
                DatagramSocket sender = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            receiver.setReceiveBufferSize(4096); // small: a few datagrams fill it
            int port = receiver.getLocalPort();
            assertEquals(0, KernelDrops.at127(port), "a fresh socket has dropped nothing");
            byte[] b = new byte[1000];
            long drops = 0;
            for (int i = 0; i < 100_000 && drops == 0; i++) { // never read: the buffer fills, the kernel drops
                sender.send(new DatagramPacket(b, b.length, receiver.getLocalSocketAddress()));
                if (i % 100 == 99) {
                    drops = KernelDrops.at127(port);
                }
            }
            assertTrue(drops > 0, "the kernel's drops at the full socket 127.0.0.1:" + port + " are counted, got "
                    + drops);
        }
    }

    @Test
    void neitherTableReadableIsMinusOne() {
        assertEquals(-1, KernelDrops.of(java.util.List.of(Path.of("/nonexistent/udp")), 47011));
    }
}
