package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.backup.ComponentBackup;

/**
 * Takes Inactivity Recognition's state back after a restart: the last activity and since when the flat
 * was watched go to the logic, so the quiet time that began before the restart keeps counting; the alert already
 * handed over and the outage (last save → now) go to the help call, so a late alert says so. Times from the
 * future are re-based on {@code now}.
 */
final class Restart {

    /** What to write to the event log. */
    record Report(List<String> problems, List<String> events) {
    }

    private Restart() {
    }

    static Report apply(ComponentBackup saved, Instant now, InactivityLogic logic, RoomActivity rooms, HelpCall help,
            AlertMail words) {
        List<String> problems = new ArrayList<>();
        List<String> events = new ArrayList<>();
        RoomActivity.Saved s = rooms.restore(saved.state(), problems);
        help.handedOverDue(s.handedOverDue());
        if (saved.savedAt().isBefore(now)) {
            help.outage(new Outage(saved.savedAt(), now));
        }
        Optional<Instant> wentBack;
        synchronized (logic) {
            logic.resume(s.last(), s.watchedFrom());
            wentBack = logic.rebase(now);
        }
        Activity a = s.last();
        if (a != null) {
            events.add("restored after a restart: last activity " + a.description() + " in " + a.roomName()
                    + " at " + words.time(a.at()) + (s.watchedFrom() == null ? "" : "; the flat was watched since "
                    + words.time(s.watchedFrom()) + ", the quiet time keeps counting") + "; last saved "
                    + words.time(saved.savedAt()));
        }
        wentBack.ifPresent(from -> events.add("saved state from the future (" + words.time(from) + ", now "
                + words.time(now) + "): quiet time counted from now"));
        return new Report(problems, events);
    }
}
