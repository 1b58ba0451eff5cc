package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.amica.busradio.base.TestRadio.frame;
import static org.tinysep.amica.busradio.base.TestRadio.keepAlive;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.device.Connection;

/** A listener that replaces one that left gets what arrived in between, in order, once; others are unaffected. */
class HandoverTest {

    private final AtomicLong now = new AtomicLong();
    private final Handover handover = new Handover(now::get);

    private static byte[] payload(int n) {
        return new byte[] {100, 5, 0, (byte) n};
    }

    /** A frame with its own sequence number and a valid payload carrying {@code n} (a light's level report). */
    private static byte[] motion(int n) {
        return AmicaCodec.encode(new AmicaFrame(1, 17, 0, n, AmicaPayloads.encode(new LightControl(n))));
    }

    private static List<Integer> numbers(List<Handover.Held> held) {
        return held.stream().map(h -> (int) h.payload()[3]).toList();
    }

    @Test
    void nothingIsHeldWhileNobodyLeft() {
        handover.record(payload(1), Instant.EPOCH);
        assertEquals(List.of(), handover.claim());
    }

    @Test
    void theReplacementGetsWhatArrivedSinceTheLeaveThenHoldingStops() {
        handover.record(payload(1), Instant.EPOCH);
        handover.listenerLeft();
        handover.record(payload(2), Instant.EPOCH);
        handover.record(payload(3), Instant.EPOCH);
        assertEquals(List.of(2, 3), numbers(handover.claim()));
        handover.record(payload(4), Instant.EPOCH);
        assertEquals(List.of(), handover.claim(), "a second newcomer gets nothing: nobody else left");
    }

    @Test
    void afterTheWindowNothingIsReplayed() {
        handover.listenerLeft();
        handover.record(payload(1), Instant.EPOCH);
        now.addAndGet(Handover.WINDOW_NANOS + 1);
        handover.record(payload(2), Instant.EPOCH);
        assertEquals(List.of(), handover.claim(), "the driver was removed, not updated");
    }

    @Test
    void holdsAtMostTheCapacityAndCountsTheRest() {
        handover.listenerLeft();
        for (int i = 0; i < Handover.CAPACITY + 5; i++) {
            handover.record(payload(i), Instant.EPOCH);
        }
        assertEquals(Handover.CAPACITY, handover.claim().size());
        assertEquals(5, handover.lost());
    }

    @Test
    void twoListenersGoneBothGetEverythingSinceTheFirstLeft() {
        handover.listenerLeft();
        handover.record(payload(1), Instant.EPOCH);
        handover.listenerLeft();
        handover.record(payload(2), Instant.EPOCH);
        assertEquals(List.of(1, 2), numbers(handover.claim()));
        handover.record(payload(3), Instant.EPOCH);
        assertEquals(List.of(1, 2, 3), numbers(handover.claim()));
    }

    @Test
    void busDeviceReplaysToTheReplacementOnlyInOrderBeforeLivePayloads() {
        TestRadio radio = new TestRadio();
        radio.feed(frame(1, 17, keepAlive(AmicaNodeType.MOVEMENT)), "udp");
        AmicaBusDevice<String> bus = radio.nodes.find(new AmicaAddress(1, 17));
        List<Integer> stayed = new ArrayList<>();
        List<Integer> old = new ArrayList<>();
        List<Integer> replacement = new ArrayList<>();
        bus.connect((source, p, at) -> stayed.add((int) p[3]));
        Connection oldConnection = bus.connect((source, p, at) -> old.add((int) p[3]));
        radio.feed(motion(1), "udp");
        oldConnection.close();
        oldConnection.close(); // twice: still one leave
        radio.feed(motion(2), "udp");
        radio.feed(motion(3), "udp");
        bus.connect((source, p, at) -> replacement.add((int) p[3]));
        radio.feed(motion(4), "udp");
        assertEquals(List.of(1, 2, 3, 4), stayed);
        assertEquals(List.of(1), old);
        assertEquals(List.of(2, 3, 4), replacement);
        List<Integer> late = new ArrayList<>();
        bus.connect((source, p, at) -> late.add((int) p[3]));
        radio.feed(motion(5), "udp");
        assertEquals(List.of(5), late, "only one listener left, so only one replacement is served");
        assertTrue(replacement.contains(5));
    }
}
