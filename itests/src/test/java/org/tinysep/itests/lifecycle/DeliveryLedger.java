package org.tinysep.itests.lifecycle;

import java.time.Instant;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Matches what the bus radio received against what movement consumers got. The bus radio hands a frame's payload
 * and its receive instant to every listener of the node's bus device; AmICA Movement passes the same instant on in
 * its {@code MovementEvent}. So each received frame is identified by (node, instant) — a multiset, as two frames of one
 * node may share an instant — and a frame whose key never reaches a movement listener was dropped.
 */
final class DeliveryLedger {

    /** One frame as the bus radio delivered it, with the test's monotonic time of delivery. */
    record Received(String node, Instant at, long nanos) {
    }

    private record Key(String node, Instant at) {
    }

    private final Queue<Received> received = new ConcurrentLinkedQueue<>();
    private final AtomicLong receivedCount = new AtomicLong();
    private final Map<Key, AtomicInteger> delivered = new ConcurrentHashMap<>();
    private final AtomicLong deliveredCount = new AtomicLong();

    /** The bus radio delivered a Motion Detection frame of {@code node}. */
    void radio(String node, Instant at) {
        received.add(new Received(node, at, System.nanoTime()));
        receivedCount.incrementAndGet();
    }

    /** A movement consumer got the event of {@code node} stamped {@code at}. */
    void consumer(String node, Instant at) {
        delivered.computeIfAbsent(new Key(node, at), k -> new AtomicInteger()).incrementAndGet();
        deliveredCount.incrementAndGet();
    }

    long radioCount() {
        return receivedCount.get();
    }

    long consumerCount() {
        return deliveredCount.get();
    }

    /** @return frames received by the radio in {@code [from, to)} (nanoTime) */
    long radioBetween(long from, long to) {
        return received.stream().filter(r -> r.nanos() >= from && r.nanos() < to).count();
    }

    /**
     * @return the frames the radio received whose event reached no movement consumer, each at the time the radio
     *         handed it over
     */
    java.util.List<Received> dropped() {
        Map<Key, Integer> left = new ConcurrentHashMap<>();
        delivered.forEach((k, n) -> left.put(k, n.get()));
        java.util.List<Received> lost = new java.util.ArrayList<>();
        for (Received r : received) {
            Key k = new Key(r.node(), r.at());
            Integer n = left.get(k);
            if (n == null || n == 0) {
                lost.add(r);
            } else {
                left.put(k, n - 1);
            }
        }
        return lost;
    }
}
