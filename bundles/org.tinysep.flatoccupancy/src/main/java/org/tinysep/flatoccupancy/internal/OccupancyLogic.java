package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;
import java.util.Optional;
import org.tinysep.api.service.Occupancy;

/**
 * The flat occupancy algorithm (our decision for the thesis's missing Figure 4.4; state diagram in the bundle
 * README). Pure logic with explicit times, so it runs in virtual time and is tested without sleeping.
 * <ul>
 * <li>Indoor motion means someone is home: OCCUPIED, and any pending leave check is cancelled.</li>
 * <li>An outer door opening while not OCCUPIED means someone arrived: OCCUPIED.</li>
 * <li>An outer door closing starts a leave check. If no indoor motion is reported within {@code leaveTimeout}
 * after the close, the flat becomes UNOCCUPIED. Motion in the first {@code exitGrace} after the close is
 * ignored: the leaving person is still seen by the hall sensor.</li>
 * </ul>
 * Pet movement and outdoor sensors are not inputs at all. Not thread-safe: the device serialises calls.
 */
final class OccupancyLogic {

    private final Duration leaveTimeout;
    private final Duration exitGrace;
    private Occupancy state = Occupancy.UNKNOWN;
    private Instant since;
    private Instant lastClose;
    private Instant leaveDeadline;

    OccupancyLogic(Duration leaveTimeout, Duration exitGrace, Instant start) {
        if (leaveTimeout.compareTo(exitGrace) <= 0) {
            throw new IllegalArgumentException("leave timeout " + leaveTimeout + " must exceed exit grace "
                    + exitGrace);
        }
        this.leaveTimeout = leaveTimeout;
        this.exitGrace = exitGrace;
        this.since = Objects.requireNonNull(start, "start");
    }

    /** Indoor motion was reported at {@code at}. */
    Optional<Occupancy> motion(Instant at) {
        if (lastClose != null && at.isBefore(lastClose.plus(exitGrace))) {
            return Optional.empty();
        }
        leaveDeadline = null;
        return change(Occupancy.OCCUPIED, at);
    }

    /** An outer door opened at {@code at}. */
    Optional<Occupancy> outerDoorOpened(Instant at) {
        return state == Occupancy.OCCUPIED ? Optional.empty() : change(Occupancy.OCCUPIED, at);
    }

    /** An outer door closed at {@code at}: someone may have left. */
    Optional<Occupancy> outerDoorClosed(Instant at) {
        lastClose = at;
        leaveDeadline = at.plus(leaveTimeout);
        return Optional.empty();
    }

    /** Time passed; ends a leave check whose deadline is reached. */
    Optional<Occupancy> tick(Instant now) {
        if (leaveDeadline == null || now.isBefore(leaveDeadline)) {
            return Optional.empty();
        }
        Instant at = leaveDeadline;
        leaveDeadline = null;
        return change(Occupancy.UNOCCUPIED, at);
    }

    private Optional<Occupancy> change(Occupancy next, Instant at) {
        if (state == next) {
            return Optional.empty();
        }
        state = next;
        since = at;
        return Optional.of(next);
    }

    Occupancy state() {
        return state;
    }

    Instant since() {
        return since;
    }

    /** @return when the pending leave check ends, empty if none is pending */
    Optional<Instant> leaveDeadline() {
        return Optional.ofNullable(leaveDeadline);
    }
}
