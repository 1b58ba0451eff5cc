package org.tinysep.runtime.internal.log;

import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;

/**
 * Event-log lines: {@code <time>\t<sequence>\t<KIND>\t<origin>\t<message>}, e.g.
 * {@code 2026-11-22T11:10:00.123Z	42	DEVICE_CREATED	amica-movement-0012	AmicaMovement "Movement 0012" created}.
 */
final class EventLines extends LineCodec<EventEntry> {

    private final LogTime times = new LogTime();

    EventLines() {
        super(EventEntry::sequence, EventEntry::time, EventEntry::origin);
    }

    @Override
    String encode(EventEntry e) {
        String origin = Escaping.escape(e.origin());
        String message = Escaping.escape(e.message());
        StringBuilder out = new StringBuilder(48 + origin.length() + message.length());
        return times.append(out, e.time()).append('\t').append(e.sequence()).append('\t').append(e.kind().name())
                .append('\t').append(origin).append('\t').append(message).toString();
    }

    @Override
    EventEntry decode(String line) {
        String[] f = Fields.split(line, 5);
        return new EventEntry(Fields.sequence(f[1]), Fields.time(f[0]), EventKind.valueOf(f[2]),
                Escaping.unescape(f[3]), Escaping.unescape(f[4]));
    }
}
