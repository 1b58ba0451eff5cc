package org.tinysep.runtime.internal.log;

import java.time.Instant;
import java.util.function.Function;
import java.util.function.ToLongFunction;

/**
 * Turns log entries into single text lines and back. A line is tab-separated fields, starting with the entry's
 * time (ISO-8601 UTC) and sequence number; text fields are escaped ({@link Escaping}) so that no field contains a
 * tab or a line break. A subclass writes and reads the fields of one entry type and names its sequence and time.
 *
 * @param <E> the entry type
 */
abstract class LineCodec<E> {

    private final ToLongFunction<E> sequence;
    private final Function<E, Instant> time;
    private final Function<E, String> origin;

    /**
     * @param sequence the entry's sequence number
     * @param time     the entry's time
     * @param origin   the entry's origin (what {@link OriginShare} keeps a share of)
     */
    LineCodec(ToLongFunction<E> sequence, Function<E, Instant> time, Function<E, String> origin) {
        this.sequence = sequence;
        this.time = time;
        this.origin = origin;
    }

    /** @return the line for {@code entry}, without a line terminator */
    abstract String encode(E entry);

    /**
     * @return the entry of a line written by {@link #encode}
     * @throws IllegalArgumentException when the line is damaged (wrong field count, bad time, kind or bytes)
     */
    abstract E decode(String line);

    final long sequence(E entry) {
        return sequence.applyAsLong(entry);
    }

    final Instant time(E entry) {
        return time.apply(entry);
    }

    final String origin(E entry) {
        return origin.apply(entry);
    }
}
