package org.tinysep.link.udp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.stream.IntStream;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** Real UDP sockets on 127.0.0.1: datagrams in reach the receiver, frames out reach the peer. */
class DatagramLinkTest {

    @Test
    void receivesDatagramsAndSendsBackToTheSourceAddress() throws Exception {
        BlockingQueue<byte[]> received = new LinkedBlockingQueue<>();
        BlockingQueue<InetSocketAddress> sources = new LinkedBlockingQueue<>();
        try (DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
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
        try (DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
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

    /**
     * Issue 17: the platform tick drains the socket so that in lock-step every frame sent before a TICK is handled
     * before its DONE, however late the receive thread runs. Here the receive thread is stuck in its first datagram
     * when the drain starts: the drain waits for it and returns only when every datagram sent before it was handled
     * completely, in order (by the receive thread or by the drain itself).
     */
    @Test
    void drainReturnsOnlyWhenEveryDatagramSentBeforeItWasHandledInOrder() throws Exception {
        List<Integer> seen = new CopyOnWriteArrayList<>();
        CountDownLatch loopBusy = new CountDownLatch(1);
        try (DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            DatagramLink.Receiver receiver = (data, length, from) -> {
                int i = data[0];
                if (i == 0) {
                    loopBusy.countDown();
                    sleep(300); // a receive thread that does not get the CPU
                }
                seen.add(i); // handled completely
            };
            transport.start(receiver);
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
            node.send(new DatagramPacket(new byte[] {0}, 1, radio));
            assertTrue(loopBusy.await(5, TimeUnit.SECONDS));
            for (int i = 1; i <= 50; i++) {
                node.send(new DatagramPacket(new byte[] {(byte) i}, 1, radio));
            }
            transport.drain(receiver);
            assertEquals(IntStream.rangeClosed(0, 50).boxed().toList(), seen, "all, in order, when drain returns");
        }
    }

    /** Drains from another thread amid a stream: every datagram handed over once, in the order sent. */
    @Test
    void theLoopAndConcurrentDrainsHandEveryDatagramOverOnceInOrder() throws Exception {
        List<Integer> seen = Collections.synchronizedList(new ArrayList<>());
        AtomicInteger drained = new AtomicInteger();
        int count = 5000;
        try (DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            DatagramLink.Receiver receiver = (data, length, from) -> seen.add(ByteBuffer.wrap(data).getInt());
            transport.start(receiver);
            CompletableFuture<Void> sent = new CompletableFuture<>();
            CompletableFuture<Void> drains = CompletableFuture.runAsync(() -> {
                while (!sent.isDone()) {
                    drained.addAndGet(transport.drain(receiver));
                }
            });
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            for (int i = 0; i < count; i++) {
                byte[] b = ByteBuffer.allocate(4).putInt(i).array();
                node.send(new DatagramPacket(b, 4, radio));
                while (seen.size() < i - 100 && System.nanoTime() < end) { // never more than the socket's buffer
                    java.util.concurrent.locks.LockSupport.parkNanos(10_000);
                }
            }
            while (seen.size() < count && System.nanoTime() < end) {
                sleep(1);
            }
            sent.complete(null);
            drains.get(5, TimeUnit.SECONDS);
            assertEquals(IntStream.range(0, count).boxed().toList(), List.copyOf(seen), drained + " drained");
        }
    }

    @Test
    void drainHandsOverWaitingDatagramsOnTheCallersThread() throws Exception {
        List<String> threads = new CopyOnWriteArrayList<>();
        try (DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
            for (int i = 0; i < 20; i++) {
                node.send(new DatagramPacket(new byte[] {(byte) i}, 1, radio));
            }
            int drained = 0;
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (drained < 20 && System.nanoTime() < end) { // loopback delivers at once; a wait, not a sleep
                drained += transport.drain((data, length, from) -> threads.add(Thread.currentThread().getName()));
            }
            assertEquals(20, drained);
            assertTrue(threads.stream().allMatch(Thread.currentThread().getName()::equals), threads.toString());
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** A datagram longer than the receive buffer arrives cut to the buffer, longer than any valid frame. */
    @Test
    void anOversizeDatagramIsSeenLongerThanAnyFrame() throws Exception {
        BlockingQueue<Integer> lengths = new LinkedBlockingQueue<>();
        try (DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
                DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            transport.start((data, length, from) -> lengths.add(length));
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
            node.send(new DatagramPacket(new byte[3000], 3000, radio));
            node.send(new DatagramPacket(new byte[12], 12, radio));
            assertEquals(DatagramLink.RECEIVE_BUFFER, lengths.poll(5, TimeUnit.SECONDS));
            assertEquals(12, lengths.poll(5, TimeUnit.SECONDS));
        }
    }

    /**
     * close() ends the receive loop by closing its socket, idle or amid a stream of datagrams: it returns well
     * before {@link LinkThread#CLOSE_WAIT}, after which it would have had to interrupt the loop.
     */
    @Test
    void closeEndsTheReceiveLoopPromptly() throws Exception {
        for (boolean streaming : new boolean[] {false, true}) {
            DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
            AtomicInteger seen = new AtomicInteger();
            CompletableFuture<Void> sender = new CompletableFuture<>();
            try (DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
                transport.start((data, length, from) -> seen.incrementAndGet());
                InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), transport.localPort());
                node.send(new DatagramPacket(new byte[1], 1, radio));
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
                while (seen.get() == 0 && System.nanoTime() < end) {
                    sleep(1);
                }
                if (streaming) {
                    CompletableFuture.runAsync(() -> {
                        while (!sender.isDone()) {
                            try {
                                node.send(new DatagramPacket(new byte[1], 1, radio));
                            } catch (IOException e) {
                                return;
                            }
                        }
                    });
                    sleep(100);
                }
                long t0 = System.nanoTime();
                transport.close();
                long millis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
                sender.complete(null);
                assertTrue(millis < LinkThread.CLOSE_WAIT.toMillis() / 2,
                        (streaming ? "streaming" : "idle") + ": close took " + millis + " ms");
            }
        }
    }

    @Test
    void sendingAfterCloseReportsAFailureInsteadOfThrowing() throws Exception {
        DatagramLink transport = DatagramLink.open("127.0.0.1", 0, 1 << 20, "test");
        transport.close();
        CompletableFuture<Exception> outcome = new CompletableFuture<>();
        transport.send(new byte[] {1}, new InetSocketAddress("127.0.0.1", 9), (f, to, e) -> outcome.complete(e));
        assertTrue(outcome.get(1, TimeUnit.SECONDS).getMessage().contains("closed"));
    }
}
