package org.tinysep.sunspot.busradio.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_A;
import static org.tinysep.sunspot.busradio.internal.TestBus.SPOT_B;
import static org.tinysep.sunspot.busradio.internal.TestBus.frame;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.delivery.OrderedDelivery;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * A packet goes to the listeners connected when it was received, as it did on the receive thread before the ordered
 * queue: a listener that connects while the packet still waits in the queue (already counted in "packets") does
 * not get it. Integration test {@code SunSpotBusRadioTest} connects right after the count and expects exactly
 * what was sent afterwards.
 */
class ListenersAtReceiptTest {

    private static final String UDP = "udp 127.0.0.1:40000";
    private final TestBus bus = new TestBus();
    private final OrderedDelivery delivery = new OrderedDelivery(bus.context, "The Sun SPOT radio",
            Duration.ofSeconds(30), 64, 64);
    private final CountDownLatch release = new CountDownLatch(1);

    @AfterEach
    void close() {
        release.countDown();
        delivery.close();
    }

    @Test
    void aListenerConnectedWhileAPacketWaitsInTheQueueDoesNotGetIt() throws Exception {
        bus.nodes.delivery(delivery);
        bus.feed(frame(SPOT_A, new TemperatureStatus(20.0)), UDP);
        bus.feed(frame(SPOT_B, new TemperatureStatus(20.0)), UDP);
        assertTrue(delivery.awaitDelivered(TestBus.TIMEOUT));
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
        assertTrue(delivery.awaitDelivered(TestBus.TIMEOUT));
        assertEquals(List.of(2), heard, "what a listener connected after packet 1 was received hears");
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
