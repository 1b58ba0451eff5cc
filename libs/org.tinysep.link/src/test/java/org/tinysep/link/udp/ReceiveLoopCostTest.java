package org.tinysep.link.udp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;

/**
 * What the receive loop spends per datagram besides the datagram's own receive, on real UDP sockets on 127.0.0.1:
 * each wait for the socket and each receive that finds nothing is a system call (and a wait a wake-up), and each
 * byte allocated on the receive thread is garbage to collect.
 */
class ReceiveLoopCostTest {

    /** Datagrams sent before the counting starts (class loading, the JIT's first compilations). */
    private static final int WARM_UP = 100;

    /**
     * A datagram that arrives alone (the loop had gone back to waiting) costs one wait and its receive: not a second
     * receive that finds the socket empty. A probe for a backlog after some wake-ups is allowed (at most one in five).
     */
    @Test
    void anIsolatedDatagramCostsOneWaitAndNoEmptyReceive() throws Exception {
        AtomicInteger handled = new AtomicInteger();
        int count = 300;
        try (DatagramLink link = DatagramLink.open("127.0.0.1", 0, 1 << 20, "cost-test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            link.start((data, length, from) -> handled.incrementAndGet());
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), link.localPort());
            long waits = 0;
            long empty = 0;
            long datagrams = 0;
            for (int i = 0; i < WARM_UP + count; i++) {
                if (i == WARM_UP) {
                    waits = link.loopWaits();
                    empty = link.loopEmptyReceives();
                    datagrams = link.loopDatagrams();
                }
                node.send(new DatagramPacket(new byte[] {(byte) i}, 1, radio));
                awaitHandled(handled, i + 1);
                LockSupport.parkNanos(TimeUnit.MICROSECONDS.toNanos(700)); // the loop goes back to waiting
            }
            waits = link.loopWaits() - waits;
            empty = link.loopEmptyReceives() - empty;
            datagrams = link.loopDatagrams() - datagrams;
            double perDatagram = (waits + empty) / (double) datagrams;
            assertEquals(count, datagrams, "every datagram handed over by the receive loop");
            assertTrue(perDatagram <= 1.2, String.format("waits and empty receives per isolated datagram: %.3f "
                    + "(%d waits, %d empty receives, %d datagrams)", perDatagram, waits, empty, datagrams));
        }
    }

    /** A backlog (the receiver was busy while datagrams queued up) is received without a wait per datagram. */
    @Test
    void aBacklogIsReceivedWithoutAWaitPerDatagram() throws Exception {
        AtomicInteger handled = new AtomicInteger();
        CountDownLatch release = new CountDownLatch(1);
        int count = 300;
        try (DatagramLink link = DatagramLink.open("127.0.0.1", 0, 1 << 20, "cost-test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            link.start((data, length, from) -> {
                if (handled.incrementAndGet() == 1) {
                    await(release); // a receiver busy for a while
                }
            });
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), link.localPort());
            node.send(new DatagramPacket(new byte[] {0}, 1, radio));
            awaitHandled(handled, 1);
            long waits = link.loopWaits();
            for (int i = 1; i <= count; i++) {
                node.send(new DatagramPacket(new byte[] {(byte) i}, 1, radio));
            }
            release.countDown();
            awaitHandled(handled, count + 1);
            waits = link.loopWaits() - waits;
            assertTrue(waits <= count / 10, waits + " waits for a backlog of " + count + " datagrams");
        }
    }

    /**
     * The receive thread allocates nothing of its own per datagram from one sender: no selected-key set entry (32
     * bytes) per wake-up; the JDK reuses the sender's address while it does not change. What remains is the JDK's:
     * its selector boxes the socket's file descriptor number to find its key, 16 bytes per wake-up once the number is
     * above 127 (the Integer cache). Measured on the receive thread itself, over isolated datagrams (a wake-up each).
     */
    @Test
    void receivingAllocatesNothingPerDatagram() throws Exception {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        AtomicInteger handled = new AtomicInteger();
        AtomicLong from = new AtomicLong();
        AtomicLong to = new AtomicLong();
        int first = 300;
        int last = 1300;
        try (DatagramLink link = DatagramLink.open("127.0.0.1", 0, 1 << 20, "cost-test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            link.start((data, length, source) -> {
                int n = handled.get() + 1;
                if (n == first) {
                    from.set(threads.getCurrentThreadAllocatedBytes());
                } else if (n == last) {
                    to.set(threads.getCurrentThreadAllocatedBytes());
                }
                handled.set(n);
            });
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), link.localPort());
            byte[] frame = {1, 2, 3, 4, 5, 6, 7, 8};
            DatagramPacket packet = new DatagramPacket(frame, frame.length, radio);
            for (int i = 0; i < last; i++) {
                node.send(packet);
                awaitHandled(handled, i + 1);
                LockSupport.parkNanos(TimeUnit.MICROSECONDS.toNanos(200));
            }
            double perDatagram = (to.get() - from.get()) / (double) (last - first);
            assertTrue(perDatagram < 24, String.format("bytes allocated on the receive thread per datagram: %.2f",
                    perDatagram));
        }
    }

    private static void awaitHandled(AtomicInteger handled, int n) {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (handled.get() < n) {
            assertTrue(System.nanoTime() < end, "datagram " + n + " not handled within 10 s");
            LockSupport.parkNanos(20_000);
        }
    }

    private static void await(CountDownLatch latch) {
        try {
            latch.await(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
