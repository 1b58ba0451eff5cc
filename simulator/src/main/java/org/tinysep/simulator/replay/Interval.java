package org.tinysep.simulator.replay;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.Objects;

/**
 * A half-open time interval {@code [start, end)}.
 *
 * @param start first instant
 * @param end   end, not before start
 */
public record Interval(LocalDateTime start, LocalDateTime end) {

    /** @throws IllegalArgumentException if end is before start */
    public Interval {
        Objects.requireNonNull(start, "start");
        Objects.requireNonNull(end, "end");
        if (end.isBefore(start)) {
            throw new IllegalArgumentException("interval ends (" + end + ") before it starts (" + start + ")");
        }
    }

    /** @return the length */
    public Duration length() {
        return Duration.between(start, end);
    }
}
