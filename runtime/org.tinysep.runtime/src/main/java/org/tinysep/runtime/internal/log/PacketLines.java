package org.tinysep.runtime.internal.log;

import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;

/**
 * Packet-log lines: {@code <time>\t<sequence>\t<DIRECTION>\t<origin>\t<hex bytes>\t<note>}, the bytes as
 * upper-case hexadecimal without separators, e.g.
 * {@code 2026-11-22T11:10:00.123Z	7	RECEIVED	node 1.17 via 127.0.0.1:47001	AA0112FF	}.
 */
final class PacketLines extends LineCodec<PacketEntry> {

    private final LogTime times = new LogTime();

    PacketLines() {
        super(PacketEntry::sequence, PacketEntry::time, PacketEntry::origin);
    }

    @Override
    String encode(PacketEntry p) {
        String origin = Escaping.escape(p.origin());
        String note = Escaping.escape(p.note());
        StringBuilder out = new StringBuilder(48 + origin.length() + 2 * p.bytes().length + note.length());
        times.append(out, p.time()).append('\t').append(p.sequence()).append('\t').append(p.direction().name())
                .append('\t').append(origin).append('\t');
        return Escaping.hex(out, p.bytes()).append('\t').append(note).toString();
    }

    @Override
    PacketEntry decode(String line) {
        String[] f = Fields.split(line, 6);
        return new PacketEntry(Fields.sequence(f[1]), Fields.time(f[0]), Direction.valueOf(f[2]),
                Escaping.unescape(f[3]), Escaping.unhex(f[4]), Escaping.unescape(f[5]));
    }
}
