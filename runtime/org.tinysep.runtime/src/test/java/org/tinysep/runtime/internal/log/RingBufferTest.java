package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class RingBufferTest {

    record Item(long seq, String text) {
    }

    private static List<Long> seqs(List<Item> items) {
        return items.stream().map(Item::seq).toList();
    }

    private static RingBuffer<Item> filled(int capacity, int count) {
        RingBuffer<Item> ring = new RingBuffer<>(capacity);
        for (int i = 0; i < count; i++) {
            String text = "e" + i;
            ring.append(seq -> new Item(seq, text));
        }
        return ring;
    }

    @Test
    void sequenceStartsAtOneAndIncreasesByOne() {
        RingBuffer<Item> ring = filled(10, 3);
        assertEquals(List.of(1L, 2L, 3L), seqs(ring.newest(10)));
        assertEquals(3, ring.lastSequence());
    }

    @Test
    void keepsOnlyTheNewestCapacityEntriesOldestFirst() {
        RingBuffer<Item> ring = filled(3, 7);
        assertEquals(3, ring.size());
        assertEquals(List.of(5L, 6L, 7L), seqs(ring.newest(100)));
        assertEquals(List.of("e4", "e5", "e6"), ring.newest(3).stream().map(Item::text).toList());
        assertEquals(List.of(6L, 7L), seqs(ring.newest(2)));
    }

    @Test
    void newestOfNothingOrNonPositiveIsEmpty() {
        assertTrue(new RingBuffer<Item>(4).newest(5).isEmpty());
        RingBuffer<Item> ring = filled(4, 2);
        assertTrue(ring.newest(0).isEmpty());
        assertTrue(ring.newest(-3).isEmpty());
    }

    @Test
    void afterReturnsTheEntriesFollowingASequenceNumber() {
        RingBuffer<Item> ring = filled(5, 8); // holds 4..8
        assertEquals(List.of(6L, 7L), seqs(ring.after(5, 2)));
        assertEquals(List.of(4L, 5L, 6L, 7L, 8L), seqs(ring.after(0, 100)), "overwritten ones are simply absent");
        assertTrue(ring.after(8, 10).isEmpty());
        assertTrue(ring.after(3, 0).isEmpty());
    }

    @Test
    void resizeKeepsTheNewestAndNumberingGoesOn() {
        RingBuffer<Item> ring = filled(5, 5);
        ring.resize(2);
        assertEquals(List.of(4L, 5L), seqs(ring.newest(10)));
        ring.append(seq -> new Item(seq, "x"));
        assertEquals(List.of(5L, 6L), seqs(ring.newest(10)));
        ring.resize(4);
        ring.append(seq -> new Item(seq, "y"));
        ring.append(seq -> new Item(seq, "z"));
        assertEquals(List.of(5L, 6L, 7L, 8L), seqs(ring.newest(10)));
        assertEquals(4, ring.capacity());
    }

    @Test
    void rejectsCapacitiesOutOfRange() {
        assertThrows(IllegalArgumentException.class, () -> new RingBuffer<Item>(0));
        assertThrows(IllegalArgumentException.class, () -> filled(3, 1).resize(RingBuffer.MAX_CAPACITY + 1));
    }

    @Test
    void aThrowingFactoryLeavesTheRingUnchanged() {
        RingBuffer<Item> ring = filled(3, 2);
        assertThrows(IllegalStateException.class, () -> ring.append(seq -> {
            throw new IllegalStateException("boom");
        }));
        ring.append(seq -> new Item(seq, "next"));
        assertEquals(List.of(1L, 2L, 3L), seqs(ring.newest(3)));
    }

    @Test
    void concurrentAppendsGetUniqueGapFreeSequenceNumbers() throws Exception {
        int threads = 4;
        int perThread = 20_000;
        RingBuffer<Item> ring = new RingBuffer<>(threads * perThread);
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            List<Future<?>> done = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                done.add(pool.submit(() -> {
                    for (int i = 0; i < perThread; i++) {
                        ring.append(seq -> new Item(seq, ""));
                        if (i % 1000 == 0) {
                            ring.newest(50); // readers run alongside writers
                        }
                    }
                }));
            }
            for (Future<?> f : done) {
                f.get(30, TimeUnit.SECONDS);
            }
        } finally {
            pool.shutdownNow();
        }
        List<Item> all = ring.newest(threads * perThread);
        assertEquals(threads * perThread, all.size());
        Set<Long> unique = new HashSet<>(seqs(all));
        assertEquals(threads * perThread, unique.size());
        for (int i = 0; i < all.size(); i++) {
            assertEquals(i + 1, all.get(i).seq(), "entries are stored in sequence order");
        }
    }
}
