package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import org.tinysep.api.service.Occupancy;

/**
 * The flat occupancy algorithm (our decision for the thesis's missing Figure 4.4; state diagram in the bundle
 * README). Pure logic with explicit times, so it runs in virtual time and is tested without sleeping.
 * <ul>
 * <li>Any indoor activity (motion, inner doors, windows and contacts, mats, flush, appliances) means someone is
 * home: OCCUPIED, and any pending leave check is cancelled.</li>
 * <li>A bed or seat mat that is ON says someone is here now: a leave check ends without UNOCCUPIED.</li>
 * <li>An outer door opening while not OCCUPIED means someone arrived: OCCUPIED.</li>
 * <li>An outer door closing starts a leave check. If no indoor motion is reported within {@code leaveTimeout}
 * after the close, the flat becomes UNOCCUPIED. Motion in the first {@code exitGrace} after the close is
 * ignored: the leaving person is still seen by the hall sensor.</li>
 * </ul>
 * Pet movement and outdoor sensors are not inputs at all. A clock that went back is re-based
 * ({@link #rebase(Instant)}): times later than {@code now} are taken as {@code now}, so fresh motion is never
 * ignored and a leave check never waits for a time from the future. Not thread-safe: the device serialises calls.
 */
final class OccupancyLogic {

    /** Times this much later than {@code now} are threads racing, not a clock that went back. */
    static final Duration CLOCK_SLACK = Duration.ofSeconds(2);

    /** What is kept across a restart (the device's backup state). */
    record Saved(Occupancy state, Instant since, Instant lastClose, Instant leaveDeadline) {
    }

    private final Duration leaveTimeout;
    private final Duration exitGrace;
    private Occupancy state = Occupancy.UNKNOWN;
    private Instant since;
    private Instant lastClose;
    private Instant leaveDeadline;
    /**
     * {@code lastClose + exitGrace}, or null without a close: kept when {@code lastClose} is set, so an activity
     * is checked against it without time arithmetic per report.
     */
    private Instant graceEnd;
    /**
     * The earliest {@code now} at which neither {@code since} nor {@code lastClose} lies beyond {@link #CLOCK_SLACK}
     * after it ({@code max(since, lastClose) - CLOCK_SLACK}): {@link #rebase} has nothing to do from then on, which
     * it sees with one comparison per report instead of adding the slack to every {@code now}.
     */
    private Instant settled;
    /** Sensors that say someone is here right now (a bed or seat mat that is ON). */
    private final Set<String> here = new TreeSet<>();

    OccupancyLogic(Duration leaveTimeout, Duration exitGrace, Instant start) {
        if (leaveTimeout.compareTo(exitGrace) <= 0) {
            throw new IllegalArgumentException("leave timeout " + leaveTimeout + " must exceed exit grace "
                    + exitGrace);
        }
        this.leaveTimeout = leaveTimeout;
        this.exitGrace = exitGrace;
        since(Objects.requireNonNull(start, "start"));
    }

    private void since(Instant at) {
        since = at;
        settle();
    }

    private void lastClose(Instant at) {
        lastClose = at;
        graceEnd = at == null ? null : at.plus(exitGrace);
        settle();
    }

    private void settle() {
        Instant latest = lastClose != null && lastClose.isAfter(since) ? lastClose : since;
        settled = latest.minus(CLOCK_SLACK);
    }

    /** Indoor motion was reported at {@code at}. */
    Optional<Occupancy> motion(Instant at) {
        return indoorActivity(at);
    }

    /**
     * Any indoor activity at {@code at}: motion, an inner door or a window changing, a mat, flush or appliance
     * turning on or off. Someone is home: OCCUPIED, and a pending leave check is cancelled, except within the exit
     * grace after the outer door closed (the leaving person).
     */
    Optional<Occupancy> indoorActivity(Instant at) {
        if (graceEnd != null && at.isBefore(graceEnd)) {
            return Optional.empty();
        }
        leaveDeadline = null;
        return change(Occupancy.OCCUPIED, at);
    }

    /**
     * A bed or seat mat turned ON ({@code on}) or OFF: activity (unless {@code first}: a first report tells the
     * resting state only), and while any is ON someone is here, so no leave check ends in UNOCCUPIED.
     */
    Optional<Occupancy> holdsPerson(String source, boolean on, boolean first, Instant at) {
        if (on) {
            here.add(source);
        } else {
            here.remove(source);
        }
        if (first) {
            return on && state != Occupancy.OCCUPIED ? change(Occupancy.OCCUPIED, at) : Optional.empty();
        }
        return indoorActivity(at);
    }

    /** A sensor went away: it no longer says anyone is here. */
    void forget(String source) {
        here.remove(source);
    }

    /** @return the sensors that say someone is here right now */
    Set<String> here() {
        return Set.copyOf(here);
    }

    /** An outer door opened at {@code at}. */
    Optional<Occupancy> outerDoorOpened(Instant at) {
        return state == Occupancy.OCCUPIED ? Optional.empty() : change(Occupancy.OCCUPIED, at);
    }

    /** An outer door closed at {@code at}: someone may have left. */
    Optional<Occupancy> outerDoorClosed(Instant at) {
        lastClose(at);
        leaveDeadline = at.plus(leaveTimeout);
        return Optional.empty();
    }

    /**
     * Counts from {@code now} what lies later than it (beyond {@link #CLOCK_SLACK}): the state's since, the last
     * door close and a pending leave check (which then runs its full timeout from now). Call before every input.
     *
     * @return the latest such time (where the clock came back from), empty when the clock did not go back
     */
    Optional<Instant> rebase(Instant now) {
        if (!now.isBefore(settled)) {
            return Optional.empty(); // nothing lies beyond the slack after now: the common case, no arithmetic
        }
        Instant limit = now.plus(CLOCK_SLACK);
        Instant from = null;
        if (since.isAfter(limit)) {
            from = since;
            since(now);
        }
        if (lastClose != null && lastClose.isAfter(limit)) {
            from = from == null || lastClose.isAfter(from) ? lastClose : from;
            lastClose(now);
            if (leaveDeadline != null) {
                leaveDeadline = now.plus(leaveTimeout);
            }
        }
        return Optional.ofNullable(from);
    }

    /** @return what to keep across a restart */
    Saved saved() {
        return new Saved(state, since, lastClose, leaveDeadline);
    }

    /**
     * After a restart: takes the saved decision back (a pending leave check too: if its deadline passed while
     * the platform was down, the next tick ends it, stamped with its deadline). Call {@link #rebase} afterwards.
     */
    void restore(Saved saved) {
        state = saved.state() == null ? Occupancy.UNKNOWN : saved.state();
        since(saved.since() == null ? since : saved.since());
        lastClose(saved.lastClose());
        leaveDeadline = saved.leaveDeadline();
    }

    /** Time passed; ends a leave check whose deadline is reached. */
    Optional<Occupancy> tick(Instant now) {
        if (leaveDeadline == null || now.isBefore(leaveDeadline)) {
            return Optional.empty();
        }
        Instant at = leaveDeadline;
        leaveDeadline = null;
        if (!here.isEmpty()) {
            return Optional.empty(); // a mat says someone is still here: nobody (or not everybody) left
        }
        return change(Occupancy.UNOCCUPIED, at);
    }

    private Optional<Occupancy> change(Occupancy next, Instant at) {
        if (state == next) {
            return Optional.empty();
        }
        state = next;
        since(at);
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
