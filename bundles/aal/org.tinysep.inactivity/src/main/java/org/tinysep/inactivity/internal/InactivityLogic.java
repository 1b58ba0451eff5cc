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
 * <li>UNOCCUPIED: NOT_WATCHING, and a raised alert is dropped (someone left through the door). UNKNOWN (Flat
 * Occupancy went away) while WATCHING: NOT_WATCHING; while in ALERT nothing changes: no one was seen leaving, so
 * the alert stays.</li>
 * <li>The clock went back (switch from virtual to real time, an NTP step, a restored time from the future):
 * {@link #rebase(Instant)} with the platform's {@code now} counts the quiet time from it, so fresh activity is
 * never taken for a late one.</li>
 * <li>After a restart {@link #resume} takes back the last activity and since when the flat was watched, so the
 * quiet time that began before the restart keeps counting.</li>
 * </ul>
 * Not thread-safe: the device serialises calls.
 */
final class InactivityLogic {

    /** Times this much later than {@code now} are threads racing, not a clock that went back. */
    static final Duration CLOCK_SLACK = Duration.ofSeconds(2);
    private static final long SLACK_SECONDS = CLOCK_SLACK.getSeconds();

    private final Duration defaultLimit;
    private Instant start;
    private InactivityState state = InactivityState.NOT_WATCHING;
    private Instant since;
    private Instant watchingFrom;
    /** The start of watching before Flat Occupancy went away (UNKNOWN), kept for a restart; else null. */
    private Instant pausedFrom;
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

    /**
     * An activity happened. A report older than the last activity is a late delivery (a bus device's hand-over,
     * lock-step frames stamped a tick late) and tells nothing new: ignored. Fresh activity is never older, since
     * the caller re-bases on the platform's {@code now} first ({@link #rebase}). An activity without a room (a
     * pendant whose wearer has not been seen in a room yet, an unplaced sensor) at the same instant as a last
     * activity with one tells nothing new either, and less about where: the room's stays, so two reports of one
     * moment give the same last activity in either order. @return the new state if it changed (an alert clears)
     */
    Optional<InactivityState> activity(Activity a) {
        if (last != null && (a.at().isBefore(last.at())
                || a.at().equals(last.at()) && a.roomUid().isEmpty() && !last.roomUid().isEmpty())) {
            return Optional.empty();
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
            pausedFrom = null;
            watchingFrom = at.isBefore(start) ? start : at;
            return change(InactivityState.WATCHING, watchingFrom);
        }
        if (occupancy == Occupancy.UNKNOWN && state == InactivityState.ALERT) {
            // Flat Occupancy went away (its bundle stopped, an update): nobody was seen leaving, the person may
            // still lie there. The alert stays; only activity, a real UNOCCUPIED or a caregiver ends it
            return Optional.empty();
        }
        alert = null;
        // UNKNOWN is no decision that anyone left (Flat Occupancy went away: an update, the platform stopping):
        // a restart resumes watching from the old start. UNOCCUPIED is: watching starts anew on arrival.
        pausedFrom = occupancy == Occupancy.UNKNOWN && watchingFrom != null ? watchingFrom : null;
        watchingFrom = null;
        return change(InactivityState.NOT_WATCHING, at);
    }

    /**
     * Counts from {@code now} what lies later than it (beyond {@link #CLOCK_SLACK}): the last activity, the start
     * of watching, the state's since. Call before every tick and activity.
     *
     * @return the latest such time (where the clock came back from), empty when the clock did not go back
     */
    Optional<Instant> rebase(Instant now) {
        Instant from = null;
        if (last != null && ahead(last.at(), now)) {
            from = last.at();
            last = last.at(now);
        }
        if (watchingFrom != null && ahead(watchingFrom, now)) {
            from = later(from, watchingFrom);
            watchingFrom = now;
        }
        if (pausedFrom != null && ahead(pausedFrom, now)) {
            pausedFrom = now;
        }
        if (ahead(since, now)) {
            from = later(from, since);
            since = now;
        }
        if (ahead(start, now)) {
            start = now;
        }
        return Optional.ofNullable(from);
    }

    /**
     * @return whether {@code t} lies more than {@link #CLOCK_SLACK} after {@code now}, i.e.
     *         {@code t.isAfter(now.plus(CLOCK_SLACK))}, without a new Instant per question (asked per activity:
     *         issue 29, item 1)
     */
    static boolean ahead(Instant t, Instant now) {
        long seconds = t.getEpochSecond() - now.getEpochSecond() - SLACK_SECONDS;
        return seconds > 0 || seconds == 0 && t.getNano() > now.getNano();
    }

    private static Instant later(Instant a, Instant b) {
        return a == null || b.isAfter(a) ? b : a;
    }

    /**
     * After a restart, before Flat Occupancy reports: takes back the last activity and, if the flat was watched
     * before, since when, so watching resumes from then and the quiet time keeps counting (an alert due during
     * the outage is raised by the next tick).
     *
     * @param saved       the last activity before the restart, or null
     * @param watchedFrom since when the flat was watched before the restart, or null if it was not
     */
    void resume(Activity saved, Instant watchedFrom) {
        if (saved != null) {
            last = saved;
        }
        if (watchedFrom != null && watchedFrom.isBefore(start)) {
            start = watchedFrom;
        }
    }

    /**
     * @return since when the flat is watched (for the backup), or was until Flat Occupancy went away; empty when
     *         not watching since someone left
     */
    Optional<Instant> watchingFrom() {
        return Optional.ofNullable(state == InactivityState.NOT_WATCHING ? pausedFrom : watchingFrom);
    }

    /** Time passed. @return ALERT when the deadline is reached now, otherwise empty */
    Optional<InactivityState> tick(Instant now) {
        Optional<Instant> deadline = deadline();
        if (state != InactivityState.WATCHING || deadline.isEmpty() || now.isBefore(deadline.get())) {
            return Optional.empty();
        }
        Instant at = deadline.get();
        alert = last == null
                ? new InactivityAlert("", "unknown room", "no activity since watching began", watchingFrom, at,
                        "no activity at all since the flat was watched; default limit " + defaultLimit.toMinutes()
                                + " min")
                : new InactivityAlert(last.roomUid(), last.roomName(), last.description(), last.at(), at,
                        last.explanation());
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

    /** @return the limit used while no activity has been seen since watching began */
    Duration defaultLimit() {
        return defaultLimit;
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
