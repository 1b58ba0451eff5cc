package org.tinysep.amica.busradio.udp.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** Real UDP sockets on 127.0.0.1: datagrams in reach the receiver, frames out reach the peer. */
class UdpTransportTest {

    @Test
    void receivesDatagramsAndSendsBackToTheSourceAddress() throws Exception {
        BlockingQueue<byte[]> received = new LinkedBlockingQueue<>();
        BlockingQueue<InetSocketAddress> sources = new LinkedBlockingQueue<>();
        try (UdpTransport transport = UdpTransport.open("127.0.0.1", 0, 1 << 20, "test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            transport.start((data, length, from) -> {
                received.add(Arrays.copyOf(data, length));
                sources.add(from);
            });
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
            for (int i = 0; i < 20; i++) {
                byte[] b = {(byte) i, 1, 2, 3};
                node.send(new DatagramPacket(b, b.length, radio));
            }
            for (int i = 0; i < 20; i++) {
                byte[] got = received.poll(5, TimeUnit.SECONDS);
                assertArrayEquals(new byte[] {(byte) i, 1, 2, 3}, got);
            }
            InetSocketAddress from = sources.poll();
            assertEquals(node.getLocalPort(), from.getPort());

            CompletableFuture<Exception> outcome = new CompletableFuture<>();
            transport.send(new byte[] {9, 8, 7}, from, (frame, to, failure) -> outcome.complete(failure));
            node.setSoTimeout(5000);
            DatagramPacket in = new DatagramPacket(new byte[64], 64);
            node.receive(in);
            assertArrayEquals(new byte[] {9, 8, 7}, Arrays.copyOf(in.getData(), in.getLength()));
            assertNull(outcome.get(5, TimeUnit.SECONDS));
        }
    }

    @Test
    void aThrowingReceiverDoesNotStopTheReceiveLoop() throws Exception {
        BlockingQueue<Integer> seen = new LinkedBlockingQueue<>();
        try (UdpTransport transport = UdpTransport.open("127.0.0.1", 0, 1 << 20, "test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            transport.start((data, length, from) -> {
                seen.add((int) data[0]);
                if (data[0] == 0) {
                    throw new IllegalStateException("handler bug");
                }
            });
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
            node.send(new DatagramPacket(new byte[] {0}, 1, radio));
            node.send(new DatagramPacket(new byte[] {1}, 1, radio));
            assertEquals(0, seen.poll(5, TimeUnit.SECONDS));
            assertEquals(1, seen.poll(5, TimeUnit.SECONDS));
        }
    }

    @Test
    void sendingAfterCloseReportsAFailureInsteadOfThrowing() throws Exception {
        UdpTransport transport = UdpTransport.open("127.0.0.1", 0, 1 << 20, "test");
        transport.close();
        CompletableFuture<Exception> outcome = new CompletableFuture<>();
        transport.send(new byte[] {1}, new InetSocketAddress("127.0.0.1", 9), (f, to, e) -> outcome.complete(e));
        assertTrue(outcome.get(1, TimeUnit.SECONDS).getMessage().contains("closed"));
    }
}
