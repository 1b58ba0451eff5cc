package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.RejectedExecutionException;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;

class EventForwarderTest {

    private final RingBuffer<EventEntry> ring = new RingBuffer<>(3);
    private final Queue<Runnable> tasks = new ArrayDeque<>();
    private final List<Long> sunk = new ArrayList<>();
    private final EventForwarder forwarder = new EventForwarder(ring, tasks::add, e -> sunk.add(e.sequence()));

    private void append(int n) {
        for (int i = 0; i < n; i++) {
            ring.append(seq -> new EventEntry(seq, Instant.EPOCH, EventKind.STATUS, "o", "m"));
            forwarder.signal();
        }
    }

    private void runTasks() {
        while (!tasks.isEmpty()) {
            tasks.poll().run();
        }
    }

    @Test
    void oneDrainIsScheduledForABurstAndDeliversAllInOrder() {
        append(3);
        assertEquals(1, tasks.size(), "signals while a drain is pending do not schedule more");
        runTasks();
        assertEquals(List.of(1L, 2L, 3L), sunk);
        append(1);
        runTasks();
        assertEquals(List.of(1L, 2L, 3L, 4L), sunk);
    }

    @Test
    void entriesOverwrittenBeforeTheDrainAreCountedAsSkipped() {
        append(5); // capacity 3: 1 and 2 are gone before the sink runs
        runTasks();
        assertEquals(List.of(3L, 4L, 5L), sunk);
        assertEquals(2, forwarder.skipped());
    }

    @Test
    void aThrowingSinkDoesNotStopTheOthers() {
        List<Long> got = new ArrayList<>();
        EventForwarder f = new EventForwarder(ring, Runnable::run, e -> {
            if (e.sequence() == 1) {
                throw new IllegalStateException("disk full");
            }
            got.add(e.sequence());
        });
        ring.append(seq -> new EventEntry(seq, Instant.EPOCH, EventKind.STATUS, "o", "m"));
        f.signal();
        ring.append(seq -> new EventEntry(seq, Instant.EPOCH, EventKind.STATUS, "o", "m"));
        f.signal();
        assertEquals(List.of(2L), got);
    }

    @Test
    void aRejectingExecutorLeavesTheEntryInTheRing() {
        EventForwarder f = new EventForwarder(ring, r -> {
            throw new RejectedExecutionException("shut down");
        }, e -> { });
        ring.append(seq -> new EventEntry(seq, Instant.EPOCH, EventKind.STATUS, "o", "m"));
        f.signal(); // must not throw
        assertEquals(1, ring.size());
    }
}
