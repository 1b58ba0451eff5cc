package org.tinysep.api.log;

import java.time.Instant;
import java.util.Objects;

/**
 * One line of the event log (thesis 3.8): what happened, when and who reported it.
 *
 * @param sequence position in the log, increasing by one per entry
 * @param time     when it happened (platform time)
 * @param kind     what kind of event
 * @param origin   UID (or name) of the driver or device that originated it
 * @param message  a sentence for the user
 */
public record EventEntry(long sequence, Instant time, EventKind kind, String origin, String message) {

    public EventEntry {
        Objects.requireNonNull(time, "time");
        Objects.requireNonNull(kind, "kind");
        origin = origin == null ? "" : origin;
        message = message == null ? "" : message;
    }
}
