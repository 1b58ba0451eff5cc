package org.tinysep.runtime.internal.log;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;

/**
 * Echoes event-log entries to a slow sink (SLF4J output) through a {@link RingDrain}, so that recording never does
 * I/O on the caller's thread. A sink that throws on one entry is logged and the next entries still go out.
 */
final class EventForwarder {

    private static final Logger LOG = LoggerFactory.getLogger(EventForwarder.class);

    private final RingDrain<EventEntry> drain;

    EventForwarder(RingBuffer<EventEntry> ring, Executor executor, Consumer<EventEntry> sink) {
        this.drain = new RingDrain<>(ring, EventEntry::sequence, executor, batch -> each(batch, sink), "logged");
    }

    private static void each(List<EventEntry> batch, Consumer<EventEntry> sink) {
        for (EventEntry e : batch) {
            try {
                sink.accept(e);
            } catch (RuntimeException ex) {
                LOG.warn("Could not log event-log entry {}: {}", e.sequence(), ex.toString());
            }
        }
    }

    /** Called after each append, from any thread: schedules a drain unless one is pending. Never blocks. */
    void signal() {
        drain.signal();
    }

    /** @return how many entries were overwritten before they could be forwarded */
    long skipped() {
        return drain.skipped();
    }
}
