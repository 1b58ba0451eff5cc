package org.tinysep.runtime.internal.log;

import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;

/**
 * Packet-log lines: {@code <time>\t<sequence>\t<DIRECTION>\t<origin>\t<hex bytes>\t<note>}, the bytes as
 * upper-case hexadecimal without separators, e.g.
 * {@code 2026-11-22T11:10:00.123Z	7	RECEIVED	node 1.17 via 127.0.0.1:47001	AA0112FF	}.
 */
final class PacketLines extends LineCodec<PacketEntry> {

    PacketLines() {
        super(PacketEntry::sequence, PacketEntry::time, PacketEntry::origin);
    }

    @Override
    String encode(PacketEntry p) {
        return p.time() + "\t" + p.sequence() + "\t" + p.direction().name() + "\t" + Escaping.escape(p.origin())
                + "\t" + Escaping.hex(p.bytes()) + "\t" + Escaping.escape(p.note());
    }

    @Override
    PacketEntry decode(String line) {
        String[] f = Fields.split(line, 6);
        return new PacketEntry(Fields.sequence(f[1]), Fields.time(f[0]), Direction.valueOf(f[2]),
                Escaping.unescape(f[3]), Escaping.unhex(f[4]), Escaping.unescape(f[5]));
    }
}
