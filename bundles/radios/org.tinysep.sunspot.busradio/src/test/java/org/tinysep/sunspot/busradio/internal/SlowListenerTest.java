package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_B;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * Issue 29: a slow listener of one Sun SPOT never stalls the link's receive thread nor the listeners of the other
 * Sun SPOTs, which keep their order; the slow one is said in plain words (the same guard as the AmICA radios').
 */
class SlowListenerTest {

    private static final String UDP = "udp 127.0.0.1:40000";
    private final TestBus bus = new TestBus();
    private final OrderedDelivery delivery = new OrderedDelivery(bus.context, "The Sun SPOT radio",
            Duration.ofMillis(150), 4_096, 64);
    private final CountDownLatch release = new CountDownLatch(1);

    @AfterEach
    void close() {
        release.countDown();
        delivery.close();
    }

    @Test
    void aStuckListenerHoldsNeitherTheReceiveThreadNorTheOtherSpots() throws Exception {
        bus.nodes.delivery(delivery);
        bus.feed(frame(SPOT_A, new TemperatureStatus(20.0)), UDP);
        bus.feed(frame(SPOT_B, new TemperatureStatus(20.0)), UDP);
        assertTrue(delivery.awaitDelivered(TestBus.TIMEOUT));
        CountDownLatch stuck = new CountDownLatch(1);
        bus.node(SPOT_A).connect((src, type, payload, at) -> {
            stuck.countDown();
            awaitRelease();
        });
        List<Integer> heard = new CopyOnWriteArrayList<>();
        bus.node(SPOT_B).connect((src, type, payload, at) -> heard.add(tenths(payload)));

        List<Integer> sent = new CopyOnWriteArrayList<>();
        ExecutorService receive = Executors.newSingleThreadExecutor(); // as a link's receive thread
        Future<?> fed = receive.submit(() -> {
            for (int i = 0; i < 200; i++) {
                bus.feed(frame(SPOT_A, TemperatureStatus.ofTenths(i)), UDP);
                bus.feed(frame(SPOT_B, TemperatureStatus.ofTenths(i)), UDP);
                sent.add(i);
            }
        });
        try {
            fed.get(5, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            release.countDown();
            fail("the receive thread was held by the stuck listener: " + sent.size() + " of 200 packet pairs handed on");
        } finally {
            receive.shutdownNow();
        }
        assertTrue(stuck.await(10, TimeUnit.SECONDS), "the stuck listener was called");
        TestBus.await("Sun SPOT B's listener heard all 200 packets", TestBus.TIMEOUT, () -> heard.size() == 200);
        assertEquals(sent, heard, "in order");
        TestBus.await("the slow listener is said", TestBus.TIMEOUT, () -> bus.problems().stream()
                .anyMatch(p -> p.contains("of Sun SPOT " + SPOT_A) && p.contains("has been busy with one payload")));
        assertTrue(delivery.quarantines() >= 1);
    }

    /**
     * A packet goes to the listeners connected when it was received, as it did on the receive thread before the
     * ordered queue: a listener that connects while the packet waits in the queue (already counted in "packets")
     * does not get it. Integration test {@code SunSpotBusRadioTest} connects right after the count and expects
     * exactly what was sent afterwards.
     */
    @Test
    void aListenerConnectedWhileAPacketWaitsInTheQueueDoesNotGetIt() throws Exception {
        try (OrderedDelivery patient = new OrderedDelivery(bus.context, "The Sun SPOT radio", Duration.ofSeconds(30),
                64, 64)) {
            bus.nodes.delivery(patient);
            bus.feed(frame(SPOT_A, new TemperatureStatus(20.0)), UDP);
            bus.feed(frame(SPOT_B, new TemperatureStatus(20.0)), UDP);
            assertTrue(patient.awaitDelivered(TestBus.TIMEOUT));
            CountDownLatch busy = new CountDownLatch(1);
            bus.node(SPOT_A).connect((src, type, payload, at) -> { // holds the dispatcher while B's packet waits
                busy.countDown();
                awaitRelease();
            });
            bus.feed(frame(SPOT_A, new TemperatureStatus(21.0)), UDP);
            assertTrue(busy.await(10, TimeUnit.SECONDS), "the dispatcher is inside A's listener");
            bus.feed(frame(SPOT_B, TemperatureStatus.ofTenths(1)), UDP); // received, counted, waiting in the queue
            List<Integer> heard = new CopyOnWriteArrayList<>();
            bus.node(SPOT_B).connect((src, type, payload, at) -> heard.add(tenths(payload)));
            release.countDown();
            bus.feed(frame(SPOT_B, TemperatureStatus.ofTenths(2)), UDP); // received after the listener connected
            assertTrue(patient.awaitDelivered(TestBus.TIMEOUT));
            assertEquals(List.of(2), heard, "what a listener connected after packet 1 was received hears");
        }
    }

    private static int tenths(byte[] payload) {
        try {
            return ((TemperatureStatus) SunSpotPayloads.decode(payload)).tenths();
        } catch (SunSpotProtocolException e) {
            throw new AssertionError(e);
        }
    }

    private void awaitRelease() {
        try {
            release.await(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
