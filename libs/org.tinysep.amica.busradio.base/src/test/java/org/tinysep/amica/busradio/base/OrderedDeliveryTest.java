package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.delivery.OrderedDelivery;

/**
 * Issue 29: a slow consumer must never stall the radio, and the order of payloads across the devices of one radio
 * is kept (the reverted per-listener queues lost it: MultiTypeNodeTest, lock-step replays).
 */
class OrderedDeliveryTest {

    private static final Duration SLOW = Duration.ofMillis(150);
    private final TestRadio radio = new TestRadio();
    private final List<OrderedDelivery> opened = new ArrayList<>();
    private final CountDownLatch release = new CountDownLatch(1);

    @AfterEach
    void close() {
        release.countDown();
        opened.forEach(OrderedDelivery::close);
    }

    private OrderedDelivery delivery(Duration slow, int capacity, int laneCapacity) {
        OrderedDelivery d = new OrderedDelivery(radio.context, "The test radio", slow, capacity, laneCapacity);
        opened.add(d);
        radio.nodes.delivery(d);
        return d;
    }

    /** Node 1.n with a keep-alive, delivered before any listener connects; @return its bus device */
    private AmicaBusDevice<String> node(int n) {
        radio.feed(frame(1, n, keepAlive(AmicaNodeType.MOVEMENT)), "sender");
        assertTrue(opened.get(0).awaitDelivered(Duration.ofSeconds(5)));
        return radio.nodes.find(new AmicaAddress(1, n));
    }

    /** The n-th payload of the test: a heater report of n % 101 percent, so neighbours are told apart. */
    private void feed(int node, int n) {
        radio.feed(frame(1, node, AmicaPayloads.encode(new HeaterControl(n % 101))), "sender");
    }

    private static String fed(int node, int n) {
        return node + ":" + n % 101;
    }

    /** @return "node:percent" for a heater report, null for anything else (the keep-alive) */
    private static String heard(int node, byte[] payload) {
        AmicaPayload p;
        try {
            p = AmicaPayloads.decode(payload);
        } catch (Exception e) {
            throw new AssertionError(e);
        }
        return p instanceof HeaterControl h ? node + ":" + h.percent() : null;
    }

    private BusRadioAmicaListener recorder(int node, List<String> into) {
        return (src, payload, at) -> {
            String h = heard(node, payload);
            if (h != null) {
                into.add(h);
            }
        };
    }

    private BusRadioAmicaListener stuck(AtomicInteger calls) {
        return (src, payload, at) -> {
            calls.incrementAndGet();
            try {
                release.await(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        };
    }

    @Test
    void theOrderAcrossDevicesIsKeptWhileOneListenerIsStuck() throws Exception {
        OrderedDelivery d = delivery(SLOW, 4_096, 4_096);
        List<String> heard = new CopyOnWriteArrayList<>();
        AmicaBusDevice<String> a = node(1);
        AmicaBusDevice<String> b = node(2);
        a.connect(recorder(1, heard));
        AtomicInteger stuckCalls = new AtomicInteger();
        b.connect(stuck(stuckCalls)); // node 2's first listener hangs on its first payload
        b.connect(recorder(2, heard));
        List<String> fed = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            int n = 1 + i % 2;
            feed(n, i);
            fed.add(fed(n, i));
        }
        waitFor(() -> heard.size() >= fed.size(), 10_000);
        assertEquals(fed, heard, "the healthy listeners of both nodes hear every payload in the radio's order");
        assertEquals(1, stuckCalls.get(), "the stuck listener is still on its first payload");
        assertEquals(1, d.quarantines(), "the stuck listener was taken out of the ordered path once");
    }

    @Test
    void aSleepingListenerHoldsNeitherTheReceiveThreadNorTheOthers() throws Exception {
        OrderedDelivery d = delivery(SLOW, 16_384, 64);
        AmicaBusDevice<String> a = node(1);
        AmicaBusDevice<String> b = node(2);
        AtomicInteger stuckCalls = new AtomicInteger();
        a.connect(stuck(stuckCalls));
        AtomicInteger other = new AtomicInteger();
        b.connect((src, payload, at) -> other.incrementAndGet());
        long start = System.nanoTime();
        for (int i = 0; i < 2_000; i++) {
            feed(1 + i % 2, i);
        }
        double feedSeconds = (System.nanoTime() - start) / 1e9;
        assertTrue(feedSeconds < 2, "the receive thread took " + feedSeconds + " s for 2,000 frames");
        waitFor(() -> other.get() >= 1_000, 5_000);
        assertEquals(1_000, other.get(), "the other node's listener got every payload while the sleeper sleeps");
        assertEquals(1, stuckCalls.get());
        // the sleeper is on its first payload, 64 are queued for it: the rest of its 1,000 are dropped, counted
        waitFor(() -> d.dropped() >= 1_000 - 1 - 64, 2_000);
        assertEquals(1_000 - 1 - 64, d.dropped(), "beyond its own queue, the sleeper's payloads are dropped");
        List<String> problems = problems();
        assertTrue(problems.stream().anyMatch(p -> p.startsWith("The listener ") && p.contains(" of AmICA node 1.1 "
                + "has been busy with one payload for over 150 ms")), problems.toString());
        assertEquals(1, problems.stream().filter(p -> p.contains("is too slow")).count(),
                "drops said once a minute: " + problems);
    }

    @Test
    void aListenerSlowForAWhileIsTakenOutAndRejoinsWhenItKeepsUp() throws Exception {
        OrderedDelivery d = delivery(SLOW, 4_096, 4_096);
        AmicaBusDevice<String> a = node(1);
        List<String> slowHeard = new CopyOnWriteArrayList<>();
        AtomicInteger calls = new AtomicInteger();
        a.connect((src, payload, at) -> {
            if (calls.incrementAndGet() == 1) { // its first payload: 600 ms, then quick again
                sleep(600);
            }
            slowHeard.add(heard(1, payload));
        });
        List<String> fed = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            feed(1, i);
            fed.add(fed(1, i));
            Thread.sleep(20);
        }
        waitFor(() -> slowHeard.size() >= 50, 5_000);
        assertEquals(fed, slowHeard, "while out of the ordered path: none lost, in order");
        assertEquals(1, d.quarantines());
        List<String> events = radio.logs.events().stream().map(e -> e.message()).toList();
        assertTrue(events.stream().anyMatch(m -> m.contains("of AmICA node 1.1 keeps up again")), events.toString());
        assertEquals(0, d.dropped());
    }

    @Test
    void aTickWaitsForWhatWasQueuedBeforeItButNotForAStuckListener() throws Exception {
        OrderedDelivery d = delivery(Duration.ofMillis(300), 4_096, 4_096);
        AmicaBusDevice<String> a = node(1);
        AtomicInteger calls = new AtomicInteger();
        a.connect((src, payload, at) -> {
            sleep(1);
            calls.incrementAndGet();
        });
        for (int i = 0; i < 200; i++) {
            feed(1, i);
        }
        assertTrue(d.awaitDelivered(Duration.ofSeconds(5)));
        assertEquals(200, calls.get(), "every payload queued before the tick reached its listener before it went on");

        AtomicInteger stuckCalls = new AtomicInteger();
        a.connect(stuck(stuckCalls));
        feed(1, 1_000);
        long start = System.nanoTime();
        assertTrue(d.awaitDelivered(Duration.ofSeconds(5)), "a stuck listener's queue counts as delivered");
        double waited = (System.nanoTime() - start) / 1e9;
        assertTrue(waited < 2, "the tick waited " + waited + " s for a stuck listener");
        assertEquals(201, calls.get());
    }

    @Test
    void aFullOrderedQueueDropsCountsAndSaysItWithoutBlockingTheReceiveThread() throws Exception {
        OrderedDelivery d = delivery(Duration.ofSeconds(60), 16, 16); // the watchdog stays out of it
        AmicaBusDevice<String> a = node(1);
        AtomicInteger stuckCalls = new AtomicInteger();
        a.connect(stuck(stuckCalls));
        feed(1, 0);
        waitFor(() -> stuckCalls.get() == 1, 5_000); // the dispatcher is inside the listener
        long start = System.nanoTime();
        for (int i = 1; i <= 100; i++) {
            feed(1, i);
        }
        assertTrue((System.nanoTime() - start) / 1e9 < 2, "the receive thread was held");
        assertEquals(100 - 16, d.dropped(), "the queue holds 16, the rest is dropped and counted");
        List<String> full = problems().stream().filter(p -> p.contains("cannot hand payloads")).toList();
        assertEquals(1, full.size(), full.toString());
        assertTrue(full.get(0).startsWith("The test radio cannot hand payloads to its devices fast enough: 1 payload"
                + " dropped since "), full.get(0));
        assertFalse(d.awaitDelivered(Duration.ofMillis(50)), "nothing moves while the dispatcher is held");
    }

    /** A driver update while its listener was out of the ordered path: its replacement gets what was queued. */
    @Test
    void whatWasQueuedForAQuarantinedListenerThatLeavesGoesToItsReplacementInOrder() throws Exception {
        OrderedDelivery d = delivery(SLOW, 4_096, 4_096);
        AmicaBusDevice<String> a = node(1);
        List<String> old = new CopyOnWriteArrayList<>();
        CountDownLatch first = new CountDownLatch(1);
        org.tinysep.api.device.Connection c = a.connect((src, payload, at) -> {
            old.add(heard(1, payload));
            first.countDown();
            sleep(400); // taken out of the ordered path on its first payload
        });
        List<String> fed = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            feed(1, i);
            fed.add(fed(1, i));
        }
        assertTrue(first.await(5, TimeUnit.SECONDS));
        waitFor(() -> d.quarantines() == 1, 2_000);
        assertTrue(d.awaitDelivered(Duration.ofSeconds(2))); // the other 9 wait in its own queue
        c.close(); // its driver is updated
        List<String> replacement = new CopyOnWriteArrayList<>();
        a.connect(recorder(1, replacement));
        feed(1, 10);
        fed.add(fed(1, 10));
        assertTrue(d.awaitDelivered(Duration.ofSeconds(2)));
        waitFor(() -> old.size() + replacement.size() >= 11, 2_000);
        assertEquals(fed.subList(0, 1), old, "the leaving listener finished the payload it was on, and no more");
        assertEquals(fed.subList(1, 11), replacement, "none lost, none twice, in order");
    }

    private List<String> problems() {
        return radio.logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).map(e -> e.message()).toList();
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void waitFor(BooleanSupplier done, long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (!done.getAsBoolean() && System.nanoTime() < end) {
            Thread.sleep(5);
        }
    }
}
