package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;

/**
 * Feeds what happens into the flat's detector ({@link InactivityLogic}) and the wearers' own watches
 * ({@link PersonWatches}): room activity, a person node's movement, Flat Occupancy and the platform's seconds, and
 * hands each change to the {@link StateAnnouncer}. The platform's time is the clock, not a report's: a late report is no
 * clock step; a clock that went back is said in plain words.
 */
final class ActivityFeed {

    private final InactivityLogic logic;
    private final RoomActivity rooms;
    private final LimitPolicy policy;
    private final AlertMail words;
    private final Supplier<PersonWatches> persons;
    private final StateAnnouncer announcer;
    private final DeviceSide side;

    ActivityFeed(InactivityLogic logic, RoomActivity rooms, LimitPolicy policy, AlertMail words,
            Supplier<PersonWatches> persons, StateAnnouncer announcer, DeviceSide side) {
        this.logic = logic;
        this.rooms = rooms;
        this.policy = policy;
        this.words = words;
        this.persons = persons;
        this.announcer = announcer;
        this.side = side;
    }

    /** Activity in a room (a movement, door, window or presence sensor), seen at the platform's {@code now}. */
    void activity(Activity a, Instant now) {
        Optional<InactivityState> change;
        Optional<Instant> wentBack;
        synchronized (logic) {
            wentBack = logic.rebase(now); // the platform's time, not the report's: a late report is no clock step
            change = logic.activity(a);
        }
        if (wentBack.isPresent()) { // no closure per activity
            clockWentBack(wentBack.get(), now);
        }
        rooms.seen(a);
        // last activity per room (and a wearer's watch), saved at most every 10 s (docs/backup.md): looked at once
        // per activity, not twice (issue 29, item 1)
        side.changed();
        if (change.isPresent()) { // the reason's closure is built on a change only, not per activity
            announcer.announce(change, a.at(), () -> a.description() + " in " + a.roomName());
        }
        said(persons.get().room(a, now));
    }

    /** A person node's movement summary: its wearer's activity, and the flat's when someone moved. */
    void personMoved(PersonNodeProvider source, MovementSummary summary, Instant now) {
        PersonWatches.Moved m = persons.get().summary(source.deviceUid(), source.person(), summary, now);
        m.events().forEach(side::event);
        personSave(m.events()); // the wearer's watch (README "System backup and restarts")
        m.activity().ifPresent(a -> { // someone moved: the flat is active too
            Optional<InactivityState> change;
            synchronized (logic) {
                logic.rebase(now);
                change = logic.activity(a);
            }
            announcer.announce(change, a.at(), a::description);
        });
    }

    /** Flat Occupancy said {@code occupancy} at {@code at}. */
    void occupancy(Occupancy occupancy, Instant at) {
        if (occupancy != Occupancy.UNKNOWN) {
            policy.occupancy(occupancy == Occupancy.UNOCCUPIED, at);
        }
        Optional<InactivityState> change;
        synchronized (logic) {
            change = logic.occupancy(occupancy, at);
        }
        announcer.announce(change, at, () -> "flat " + StateAnnouncer.lower(occupancy));
        said(persons.get().occupancy(occupancy, at));
    }

    /** The platform's second {@code now}: limits reached, the flat's and each wearer's. */
    void tick(Instant now) {
        Optional<InactivityState> change;
        Optional<Instant> wentBack;
        synchronized (logic) {
            wentBack = logic.rebase(now);
            change = logic.tick(now);
        }
        wentBack.ifPresent(from -> clockWentBack(from, now));
        announcer.announce(change, now, () -> "limit reached");
        said(persons.get().tick(now)); // a wearer's alert raised or handed on: not handed on twice after a restart
    }

    /** What the wearers' watches said goes to the event log, and a watch that said something is saved at once. */
    private void said(List<String> said) {
        if (!said.isEmpty()) {
            said.forEach(side::event);
            side.save();
        }
    }

    /**
     * A wearer's watch changed: saved at once when it said something (a state change, a hand-over, worn or not
     * worn), else at most every 10 s like the flat's activity (docs/backup.md).
     */
    private void personSave(List<String> said) {
        if (said.isEmpty()) {
            side.changed();
        } else {
            side.save();
        }
    }

    /** The clock went back: says so in plain words (the logic already counts the quiet time from now). */
    private void clockWentBack(Instant from, Instant now) {
        String room;
        synchronized (logic) {
            room = logic.lastActivity().map(Activity::roomName).orElse("");
        }
        side.event("clock went back from " + words.time(from) + " to " + words.time(now) + ": quiet time"
                + (room.isEmpty() ? "" : " in " + room) + " counted from now");
        side.save();
    }
}
