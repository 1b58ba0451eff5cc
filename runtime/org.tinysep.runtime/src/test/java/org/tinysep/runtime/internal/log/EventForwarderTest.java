package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.RejectedExecutionException;
import org.junit.jupiter.api.Test;
import org.slf4j.Logger;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;

class EventForwarderTest {

    private final Queue<Runnable> tasks = new ArrayDeque<>();
    private final List<Long> sunk = new ArrayList<>();
    private final EventForwarder forwarder = new EventForwarder(e -> e.kind() != EventKind.DEVICE_EVENT, tasks::add,
            e -> sunk.add(e.sequence()));

    private static EventEntry entry(long seq, EventKind kind) {
        return new EventEntry(seq, Instant.EPOCH, kind, "o", "m");
    }

    private void offer(long from, long to, EventKind kind) {
        for (long i = from; i <= to; i++) {
            forwarder.offer(entry(i, kind));
        }
    }

    private void runTasks() {
        while (!tasks.isEmpty()) {
            tasks.poll().run();
        }
    }

    @Test
    void oneDrainIsScheduledForABurstAndDeliversAllInSequenceOrder() {
        forwarder.offer(entry(2, EventKind.STATUS)); // two threads: the later sequence number offered first
        forwarder.offer(entry(1, EventKind.STATUS));
        forwarder.offer(entry(3, EventKind.STATUS));
        assertEquals(1, tasks.size(), "offers while a drain is pending do not schedule more");
        runTasks();
        assertEquals(List.of(1L, 2L, 3L), sunk);
        offer(4, 4, EventKind.PROBLEM);
        runTasks();
        assertEquals(List.of(1L, 2L, 3L, 4L), sunk);
    }

    @Test
    void entriesTheSinkDoesNotWantWakeNoThreadAndAreNotCountedAsDropped() {
        offer(1, 5000, EventKind.DEVICE_EVENT);
        assertEquals(0, tasks.size(), "a device's events at INFO schedule no echo");
        offer(5001, 5001, EventKind.STATUS);
        runTasks();
        assertEquals(List.of(5001L), sunk);
        assertEquals(0, forwarder.skipped());
    }

    @Test
    void entriesBeyondTheCapacityAreDroppedAndCounted() {
        offer(1, EventForwarder.CAPACITY + 2, EventKind.STATUS);
        runTasks();
        assertEquals(EventForwarder.CAPACITY, sunk.size());
        assertEquals(2, forwarder.skipped());
        assertEquals(EventForwarder.CAPACITY, sunk.get(sunk.size() - 1));
    }

    @Test
    void aThrowingSinkDoesNotStopTheOthers() {
        List<Long> got = new ArrayList<>();
        EventForwarder f = new EventForwarder(e -> true, Runnable::run, e -> {
            if (e.sequence() == 1) {
                throw new IllegalStateException("disk full");
            }
            got.add(e.sequence());
        });
        f.offer(entry(1, EventKind.STATUS));
        f.offer(entry(2, EventKind.STATUS));
        assertEquals(List.of(2L), got);
    }

    @Test
    void aRejectingExecutorDoesNotThrowAndTheNextOfferTriesAgain() {
        List<Runnable> accepted = new ArrayList<>();
        boolean[] reject = {true};
        EventForwarder f = new EventForwarder(e -> true, r -> {
            if (reject[0]) {
                throw new RejectedExecutionException("shut down");
            }
            accepted.add(r);
        }, e -> sunk.add(e.sequence()));
        f.offer(entry(1, EventKind.STATUS)); // must not throw
        reject[0] = false;
        f.offer(entry(2, EventKind.STATUS));
        accepted.forEach(Runnable::run);
        assertEquals(List.of(1L, 2L), sunk);
    }

    @Test
    void aDevicesEventsAreEchoedOnlyAtDebugEveryOtherKindAtInfo() {
        Logger info = logger(false, true);
        Logger debug = logger(true, true);
        assertFalse(EventLogService.echoed(EventKind.DEVICE_EVENT, info));
        assertTrue(EventLogService.echoed(EventKind.DEVICE_EVENT, debug));
        for (EventKind k : EventKind.values()) {
            if (k != EventKind.DEVICE_EVENT) {
                assertTrue(EventLogService.echoed(k, info), k.name());
            }
        }
        assertFalse(EventLogService.echoed(EventKind.PROBLEM, logger(false, false)));
    }

    private static Logger logger(boolean debug, boolean info) {
        return (Logger) Proxy.newProxyInstance(Logger.class.getClassLoader(), new Class<?>[] {Logger.class},
                (p, m, a) -> switch (m.getName()) {
                    case "isDebugEnabled" -> debug;
                    case "isInfoEnabled" -> info;
                    default -> throw new UnsupportedOperationException(m.getName());
                });
    }
}
