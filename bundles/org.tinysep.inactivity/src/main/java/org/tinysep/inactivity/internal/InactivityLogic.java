package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;
import java.util.Optional;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;

/**
 * The inactivity algorithm (thesis 4.4.4.1, Figure 4.5; state diagram in the bundle README). Pure logic with
 * explicit times, so it runs in virtual time and is tested without sleeping.
 * <ul>
 * <li>Every activity is remembered, watching or not; it clears a raised alert.</li>
 * <li>Only while the flat is OCCUPIED is it WATCHING: the deadline is the later of the last activity and the
 * start of watching, plus the limit of the last activity's room.</li>
 * <li>A tick at or after the deadline raises the alert once (stamped with the deadline); further ticks do
 * nothing until the next activity.</li>
 * <li>UNOCCUPIED or UNKNOWN: NOT_WATCHING, and a raised alert is dropped (someone left through the door).</li>
 * </ul>
 * Not thread-safe: the device serialises calls.
 */
final class InactivityLogic {

    private final Duration defaultLimit;
    private final Instant start;
    private InactivityState state = InactivityState.NOT_WATCHING;
    private Instant since;
    private Instant watchingFrom;
    private Activity last;
    private InactivityAlert alert;

    /**
     * @param defaultLimit the limit used while no activity has been seen since watching began
     * @param start        when the device began observing; nothing before it is known
     */
    InactivityLogic(Duration defaultLimit, Instant start) {
        this.defaultLimit = Objects.requireNonNull(defaultLimit, "defaultLimit");
        this.start = Objects.requireNonNull(start, "start");
        this.since = start;
    }

    /** An activity happened. @return the new state if it changed (an alert clears) */
    Optional<InactivityState> activity(Activity a) {
        if (last != null && a.at().isBefore(last.at())) {
            return Optional.empty(); // a late report of something older than what we know
        }
        last = a;
        alert = null;
        return state == InactivityState.ALERT ? change(InactivityState.WATCHING, a.at()) : Optional.empty();
    }

    /** The flat's occupancy is {@code occupancy} since {@code at}. @return the new state if it changed */
    Optional<InactivityState> occupancy(Occupancy occupancy, Instant at) {
        if (occupancy == Occupancy.OCCUPIED) {
            if (state != InactivityState.NOT_WATCHING) {
                return Optional.empty();
            }
            watchingFrom = at.isBefore(start) ? start : at;
            return change(InactivityState.WATCHING, watchingFrom);
        }
        alert = null;
        watchingFrom = null;
        return change(InactivityState.NOT_WATCHING, at);
    }

    /** Time passed. @return ALERT when the deadline is reached now, otherwise empty */
    Optional<InactivityState> tick(Instant now) {
        Optional<Instant> deadline = deadline();
        if (state != InactivityState.WATCHING || deadline.isEmpty() || now.isBefore(deadline.get())) {
            return Optional.empty();
        }
        Instant at = deadline.get();
        alert = last == null
                ? new InactivityAlert("", "unknown room", "no activity since watching began", watchingFrom, at)
                : new InactivityAlert(last.roomUid(), last.roomName(), last.description(), last.at(), at);
        return change(InactivityState.ALERT, at);
    }

    /** @return when the alert will be raised if nothing happens, empty when not watching */
    Optional<Instant> deadline() {
        if (state != InactivityState.WATCHING) {
            return Optional.empty();
        }
        if (last == null) {
            return Optional.of(watchingFrom.plus(defaultLimit));
        }
        Instant from = last.at().isAfter(watchingFrom) ? last.at() : watchingFrom;
        return Optional.of(from.plus(last.limit()));
    }

    private Optional<InactivityState> change(InactivityState next, Instant at) {
        if (state == next) {
            return Optional.empty();
        }
        state = next;
        since = at;
        return Optional.of(next);
    }

    InactivityState state() {
        return state;
    }

    Instant since() {
        return since;
    }

    Optional<InactivityAlert> alert() {
        return Optional.ofNullable(alert);
    }

    Optional<Activity> lastActivity() {
        return Optional.ofNullable(last);
    }
}
