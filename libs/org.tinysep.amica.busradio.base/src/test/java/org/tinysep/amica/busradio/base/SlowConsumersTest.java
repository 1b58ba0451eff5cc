package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.log.EventKind;

/**
 * Issue 29: a slow consumer must never stall the radio. A listener of one node sleeps 5 s per payload; a flood of
 * UDP frames on 127.0.0.1 for that node and another is still received and decoded at the pace of the receive
 * loop, the other node's listener gets every payload, and what the slow one missed is counted and said.
 */
class SlowConsumersTest {

    private static final int FRAMES_PER_NODE = 3_000;
    private static final int QUEUE = 512;
    private final TestRadio radio = new TestRadio();
    private final SlowConsumers delivery = new SlowConsumers(radio.context, QUEUE);
    private final ExecutorService loop = Executors.newSingleThreadExecutor();

    @AfterEach
    void close() {
        loop.shutdownNow();
        delivery.close();
    }

    @Test
    void aListenerThatSleepsHoldsNeitherTheReceiveThreadNorTheOtherListeners() throws Exception {
        radio.nodes.delivery(delivery);
        radio.feed(frame(1, 1, keepAlive(AmicaNodeType.MOVEMENT)), "sender");
        radio.feed(frame(1, 2, keepAlive(AmicaNodeType.MOVEMENT)), "sender");
        AtomicInteger slowCalls = new AtomicInteger();
        AtomicInteger fastCalls = new AtomicInteger();
        radio.nodes.find(new AmicaAddress(1, 1)).connect((src, payload, at) -> {
            slowCalls.incrementAndGet();
            try {
                Thread.sleep(5_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        radio.nodes.find(new AmicaAddress(1, 2)).connect((src, payload, at) -> fastCalls.incrementAndGet());

        AtomicInteger read = new AtomicInteger();
        try (DatagramSocket receiver = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
                DatagramSocket sender = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            receiver.setSoTimeout(100);
            Future<?> receiving = loop.submit(() -> { // the bus radio's receive loop: read, hand to the frame logic
                byte[] buf = new byte[512];
                DatagramPacket p = new DatagramPacket(buf, buf.length);
                while (!Thread.currentThread().isInterrupted() && read.get() < 2 * FRAMES_PER_NODE) {
                    try {
                        receiver.receive(p);
                    } catch (SocketTimeoutException e) {
                        continue;
                    }
                    radio.handler.datagram(buf, p.getLength(), p.getSocketAddress().toString());
                    read.incrementAndGet();
                }
                return null;
            });
            long start = System.nanoTime();
            long deadline = start + Duration.ofSeconds(8).toNanos();
            byte[] motion = AmicaPayloads.encode(new MotionDetection(true));
            int sent = 0;
            while (sent < 2 * FRAMES_PER_NODE && System.nanoTime() < deadline) {
                if (sent - read.get() >= 100) { // at most 100 in flight: no kernel drops, as fast as the loop takes
                    Thread.onSpinWait();
                    continue;
                }
                byte[] f = frame(1, 1 + sent % 2, motion);
                sender.send(new DatagramPacket(f, f.length, receiver.getLocalSocketAddress()));
                sent++;
            }
            waitFor(() -> read.get() >= 2 * FRAMES_PER_NODE, deadline);
            double seconds = (System.nanoTime() - start) / 1e9;
            assertEquals(2 * FRAMES_PER_NODE, read.get(), "frames received and decoded in " + seconds
                    + " s while one listener sleeps 5 s per payload (sent " + sent + ")");
            assertTrue(seconds < 5, "the flood took " + seconds + " s: the receive thread waited for the sleeper");
            receiving.get(1, TimeUnit.SECONDS);
        }
        waitFor(() -> fastCalls.get() >= FRAMES_PER_NODE, System.nanoTime() + Duration.ofSeconds(5).toNanos());
        assertEquals(FRAMES_PER_NODE, fastCalls.get(), "the other node's listener got every payload");
        assertEquals(1, slowCalls.get(), "the sleeper is still on its first payload");
        assertEquals(FRAMES_PER_NODE - 1 - QUEUE, delivery.dropped(), "beyond its queue, its payloads are dropped");
        String problem = radio.logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM)
                .map(e -> e.message()).filter(m -> m.contains("is too slow")).findFirst().orElse("(none)");
        assertTrue(problem.startsWith("The listener ") && problem.contains(" of AmICA node 1.1 is too slow: 1 payload "
                + "dropped since ") && problem.contains("The radio goes on receiving"), problem);
    }

    @Test
    void aTickWaitsForWhatItHandedOver() {
        SlowConsumers roomy = new SlowConsumers(radio.context); // a queue of 4,096: nothing dropped
        radio.nodes.delivery(roomy);
        radio.feed(frame(1, 2, keepAlive(AmicaNodeType.MOVEMENT)), "sender");
        AtomicInteger calls = new AtomicInteger();
        radio.nodes.find(new AmicaAddress(1, 2)).connect((src, payload, at) -> calls.incrementAndGet());
        for (int i = 0; i < 500; i++) {
            radio.feed(frame(1, 2, AmicaPayloads.encode(new MotionDetection(true))), "sender");
        }
        try {
            assertTrue(roomy.awaitIdle(Duration.ofSeconds(5)));
            assertEquals(500, calls.get(), "every payload delivered, in the tick, before it goes on");
        } finally {
            roomy.close();
        }
    }

    /** A listener that leaves (its driver is updated) with payloads still queued: its replacement gets them. */
    @Test
    void whatWasQueuedForALeavingListenerGoesToItsReplacementInOrder() throws Exception {
        SlowConsumers roomy = new SlowConsumers(radio.context);
        try {
            radio.nodes.delivery(roomy);
            radio.feed(frame(1, 2, keepAlive(AmicaNodeType.MOVEMENT)), "sender");
            java.util.concurrent.CountDownLatch release = new java.util.concurrent.CountDownLatch(1);
            java.util.List<String> old = new java.util.concurrent.CopyOnWriteArrayList<>();
            java.util.List<String> replacement = new java.util.concurrent.CopyOnWriteArrayList<>();
            AmicaBusDevice<String> node = radio.nodes.find(new AmicaAddress(1, 2));
            org.tinysep.api.device.Connection c = node.connect((src, payload, at) -> {
                old.add(java.util.Arrays.toString(payload));
                try {
                    release.await(5, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            java.util.List<String> fed = new java.util.ArrayList<>();
            for (int i = 0; i < 11; i++) { // motion, no motion, motion, …
                byte[] p = AmicaPayloads.encode(new MotionDetection(i % 2 == 0));
                fed.add(java.util.Arrays.toString(p));
                if (i < 10) {
                    radio.feed(frame(1, 2, p), "sender");
                }
            }
            waitFor(() -> old.size() == 1, System.nanoTime() + Duration.ofSeconds(5).toNanos());
            c.close(); // the old driver's device leaves while it is still on payload 1
            release.countDown();
            node.connect((src, payload, at) -> replacement.add(java.util.Arrays.toString(payload)));
            radio.feed(frame(1, 2, AmicaPayloads.encode(new MotionDetection(true))), "sender"); // fed[10]
            assertTrue(roomy.awaitIdle(Duration.ofSeconds(5)));
            assertEquals(fed.subList(0, 1), old, "the leaving listener finished the payload it was on");
            assertEquals(fed.subList(1, 11), replacement, "none lost, none twice, in order");
        } finally {
            roomy.close();
        }
    }

    private static void waitFor(java.util.function.BooleanSupplier done, long deadlineNanos)
            throws InterruptedException {
        while (!done.getAsBoolean() && System.nanoTime() < deadlineNanos) {
            Thread.sleep(5);
        }
    }
}
