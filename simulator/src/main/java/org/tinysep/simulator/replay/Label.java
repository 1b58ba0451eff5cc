package org.tinysep.simulator.replay;

import java.time.LocalDateTime;
import java.util.Objects;

/**
 * One labelled activity interval, for evaluation only. Kept exactly as recorded: the Ordonez Home A file holds three
 * labels whose end lies before their start; {@link #isProper()} tells them apart and evaluation skips them.
 *
 * @param start    start (local time)
 * @param end      end (local time)
 * @param activity activity name as recorded, e.g. {@code Leaving}, {@code Spare_Time/TV}
 * @param resident resident, empty if the recording has one resident only
 */
public record Label(LocalDateTime start, LocalDateTime end, String activity, String resident) {

    /** @throws NullPointerException if a field is null */
    public Label {
        Objects.requireNonNull(start, "start");
        Objects.requireNonNull(end, "end");
        Objects.requireNonNull(activity, "activity");
        Objects.requireNonNull(resident, "resident");
    }

    /** @return true if the label ends after it starts */
    public boolean isProper() {
        return end.isAfter(start);
    }
}
