package org.tinysep.simulator.measure;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.util.List;
import org.junit.jupiter.api.Test;

class KernelDropsTest {

    @Test
    void aJvmSocketThatNeverReadsShowsItsDropsAlthoughTheKernelListsItInUdp6() throws Exception {
        assumeTrue(Files.isReadable(KernelDrops.TABLES.get(0)), "Linux /proc/net/udp");
        InetAddress loopback = InetAddress.getByName("127.0.0.1");
        try (DatagramSocket full = new DatagramSocket(null); DatagramSocket sender = new DatagramSocket(0, loopback)) {
            full.setReceiveBufferSize(2048); // the kernel doubles and rounds it up: a few datagrams fit
            full.bind(new InetSocketAddress(loopback, 0));
            int port = full.getLocalPort();
            byte[] payload = new byte[512];
            long deadline = System.nanoTime() + 20_000_000_000L;
            int sent = 0;
            // bounded: at most 20 s and 200,000 datagrams to 127.0.0.1; stops once the kernel reports drops
            while (KernelDrops.at(port) <= 0 && System.nanoTime() < deadline && sent < 200_000) {
                for (int i = 0; i < 200; i++, sent++) {
                    sender.send(new DatagramPacket(payload, payload.length, loopback, port));
                }
            }
            long drops = KernelDrops.at(port);
            System.out.printf("KernelDropsTest: %d datagrams sent to a socket that never reads: %d dropped "
                    + "(udp %d, udp6 %d)%n", sent, drops, KernelDrops.at(port, List.of(KernelDrops.TABLES.get(0))),
                    KernelDrops.at(port, List.of(KernelDrops.TABLES.get(1))));
            assertTrue(drops > 0, "the kernel's drops at the full socket are seen (udp and udp6)");
        }
    }

    @Test
    void linesOfBothTablesAreMatchedByLocalPort() {
        List<String> udp = List.of(
            "  sl  local_address rem_address   st tx_queue rx_queue tr tm->when retrnsmt   uid  timeout inode ref pointer drops",
            "  12: 0100007F:B7AB 00000000:0000 07 00000000:00000000 00:00000000 00000000  1000        0 1 2 0000000000000000 5");
        List<String> udp6 = List.of(
            "  sl  local_address                         remote_address                        st tx_queue rx_queue tr tm->when retrnsmt   uid  timeout inode ref pointer drops",
            "  40: 0000000000000000FFFF00000100007F:B7AB 00000000000000000000000000000000:0000 07 00000000:00000000 00:00000000 00000000  1000        0 3 2 0000000000000000 1234",
            "  41: 0000000000000000FFFF00000100007F:B7AC 00000000000000000000000000000000:0000 07 00000000:00000000 00:00000000 00000000  1000        0 4 2 0000000000000000 99");
        assertEquals(5, KernelDrops.drops(udp, 0xB7AB));
        assertEquals(1234, KernelDrops.drops(udp6, 0xB7AB));
        assertEquals(0, KernelDrops.drops(udp6, 0xB7AD));
    }
}
