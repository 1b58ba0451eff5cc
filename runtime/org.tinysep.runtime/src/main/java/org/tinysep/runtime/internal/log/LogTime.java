package org.tinysep.runtime.internal.log;

import java.time.Instant;

/**
 * Writes an {@link Instant} exactly as {@link Instant#toString()} does (ISO-8601 UTC, the fraction in groups of three
 * digits, none for a whole second), but formats the date and time of day once per second: log lines come thousands
 * a second, and {@code Instant.toString()} (a {@code DateTimeFormatter} per call) was a third of the packet-log
 * writer's time. Safe for any number of threads (the cache is one immutable value).
 */
final class LogTime {

    /** The second last formatted and its text up to the seconds, e.g. {@code 2026-11-22T11:10:00}. */
    private record Second(long epochSecond, String text) {
    }

    private volatile Second last = new Second(0, "1970-01-01T00:00:00");

    /** Appends {@code t} as {@link Instant#toString()} writes it. */
    StringBuilder append(StringBuilder out, Instant t) {
        Second s = last;
        if (s.epochSecond() != t.getEpochSecond()) {
            String whole = Instant.ofEpochSecond(t.getEpochSecond()).toString(); // ends with 'Z'
            s = new Second(t.getEpochSecond(), whole.substring(0, whole.length() - 1));
            last = s;
        }
        out.append(s.text());
        int nano = t.getNano();
        if (nano != 0) {
            out.append('.');
            if (nano % 1_000_000 == 0) {
                digits(out, nano / 1_000_000, 3);
            } else if (nano % 1_000 == 0) {
                digits(out, nano / 1_000, 6);
            } else {
                digits(out, nano, 9);
            }
        }
        return out.append('Z');
    }

    private static void digits(StringBuilder out, int value, int width) {
        int start = out.length();
        out.append(value);
        for (int pad = width - (out.length() - start); pad > 0; pad--) {
            out.insert(start, '0');
        }
    }
}
