package org.tinysep.runtime.internal;

import java.time.Instant;

/**
 * Turns log entries into single text lines and back. A line is tab-separated fields, starting with the entry's
 * time (ISO-8601 UTC) and sequence number; text fields are escaped ({@link Escaping}) so that no field contains a
 * tab or a line break.
 *
 * @param <E> the entry type
 */
interface LineCodec<E> {

    /** @return the line for {@code entry}, without a line terminator */
    String encode(E entry);

    /**
     * @return the entry of a line written by {@link #encode}
     * @throws IllegalArgumentException when the line is damaged (wrong field count, bad time, kind or bytes)
     */
    E decode(String line);

    long sequence(E entry);

    Instant time(E entry);
}
