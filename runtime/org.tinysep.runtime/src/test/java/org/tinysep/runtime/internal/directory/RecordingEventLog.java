package org.tinysep.runtime.internal.directory;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/** An {@link EventLog} that keeps everything in a list, for checking what was announced. */
final class RecordingEventLog implements EventLog {

    final List<EventEntry> entries = new ArrayList<>();

    @Override
    public synchronized void record(EventKind kind, String origin, String message) {
        entries.add(new EventEntry(entries.size() + 1, Instant.EPOCH, kind, origin, message));
    }

    @Override
    public synchronized List<EventEntry> recent(int max) {
        return List.copyOf(entries.subList(Math.max(0, entries.size() - max), entries.size()));
    }
}
