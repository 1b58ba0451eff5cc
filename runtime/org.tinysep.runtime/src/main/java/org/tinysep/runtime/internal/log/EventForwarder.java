package org.tinysep.runtime.internal.log;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Predicate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;

/**
 * Echoes the event-log entries a sink wants ({@code echoed}) to that slow sink (SLF4J output) on its own executor,
 * so that recording never does I/O on the caller's thread; an entry the sink does not want costs one test and
 * wakes no thread (at the default level a device's events are not echoed: they come by the thousand a second).
 * At most {@link #CAPACITY} entries wait; more are dropped, counted and reported once per gap. A sink that throws
 * on one entry is logged and the next entries still go out.
 */
final class EventForwarder {

    private static final Logger LOG = LoggerFactory.getLogger(EventForwarder.class);
    /** How many entries may wait for the sink. */
    static final int CAPACITY = 1024;

    private final Predicate<EventEntry> echoed;
    private final Executor executor;
    private final Consumer<EventEntry> sink;
    private final ConcurrentLinkedQueue<EventEntry> waiting = new ConcurrentLinkedQueue<>();
    private final AtomicInteger count = new AtomicInteger();
    private final AtomicBoolean scheduled = new AtomicBoolean();
    private final AtomicLong skipped = new AtomicLong();
    private long reported; // the drain's: skipped entries already reported

    EventForwarder(Predicate<EventEntry> echoed, Executor executor, Consumer<EventEntry> sink) {
        this.echoed = echoed;
        this.executor = executor;
        this.sink = sink;
    }

    /** Called after each append, from any thread: queues the entry if the sink wants it. Never blocks. */
    void offer(EventEntry e) {
        if (!echoed.test(e)) {
            return;
        }
        if (count.incrementAndGet() > CAPACITY) {
            count.decrementAndGet();
            skipped.incrementAndGet();
        } else {
            waiting.offer(e);
        }
        if (scheduled.compareAndSet(false, true)) {
            try {
                executor.execute(this::drain);
            } catch (RejectedExecutionException ex) {
                scheduled.set(false); // shutting down: the entry stays in the log, only its echo is lost
            }
        }
    }

    private void drain() {
        scheduled.set(false); // entries offered from now on schedule another drain
        long s = skipped.get();
        if (s > reported) {
            LOG.warn("{} event-log entries were dropped before they could be logged", s - reported);
            reported = s;
        }
        List<EventEntry> batch = new ArrayList<>();
        for (EventEntry e; (e = waiting.poll()) != null; ) {
            count.decrementAndGet();
            batch.add(e);
        }
        batch.sort(Comparator.comparingLong(EventEntry::sequence)); // threads may offer out of sequence order
        for (EventEntry e : batch) {
            try {
                sink.accept(e);
            } catch (RuntimeException ex) {
                LOG.warn("Could not log event-log entry {}: {}", e.sequence(), ex.toString());
            }
        }
    }

    /** @return how many wanted entries were dropped because {@link #CAPACITY} entries were waiting */
    long skipped() {
        return skipped.get();
    }
}
