package org.tinysep.runtime.internal;

import java.time.DateTimeException;
import java.time.Instant;

/** Splitting and parsing the fields of a log line; every failure is an {@link IllegalArgumentException}. */
final class Fields {

    private Fields() {
    }

    /** @return exactly {@code n} tab-separated fields */
    static String[] split(String line, int n) {
        String[] f = line.split("\t", -1);
        if (f.length != n) {
            throw new IllegalArgumentException(f.length + " fields instead of " + n);
        }
        return f;
    }

    static long sequence(String s) {
        long v = Long.parseLong(s); // NumberFormatException is an IllegalArgumentException
        if (v < 1) {
            throw new IllegalArgumentException("sequence " + v);
        }
        return v;
    }

    static Instant time(String s) {
        try {
            return Instant.parse(s);
        } catch (DateTimeException e) {
            throw new IllegalArgumentException("bad time '" + s + "'", e);
        }
    }
}
