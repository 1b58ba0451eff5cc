package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.api.backup.ComponentBackup;

/**
 * The Inactivity Recognition device's state in its backup (docs/backup.md): the last activity per room, since when
 * the flat was watched, the alert already handed over ({@link Restart}) and each wearer's watch
 * ({@link PersonBackup}).
 */
final class InactivityBackup {

    /** What a restore said: entries for the event log and problems. */
    record Restored(List<String> events, List<String> problems) {
    }

    private InactivityBackup() {
    }

    static Map<String, String> state(InactivityLogic logic, RoomActivity rooms, HelpCall help,
            PersonWatches persons) {
        Map<String, String> state;
        synchronized (logic) {
            state = new LinkedHashMap<>(rooms.state(logic.lastActivity().orElse(null),
                    logic.watchingFrom().orElse(null), help.handedOverDue()));
        }
        state.putAll(persons.state()); // each wearer's watch (PersonBackup)
        return state;
    }

    /**
     * After a restart: the last activity, since when the flat was watched and the alert already handed over come
     * back, so the quiet time that began before keeps counting once Flat Occupancy (restored too) says OCCUPIED;
     * an alert that fell due meanwhile is raised by the first tick and says it is late. Times from the future are
     * counted from now. Each wearer's own watch comes back too.
     */
    static Restored restore(ComponentBackup saved, Instant now, InactivityLogic logic, RoomActivity rooms,
            HelpCall help, AlertMail words, PersonWatches persons) {
        Restart.Report r = Restart.apply(saved, now, logic, rooms, help, words);
        List<String> problems = new ArrayList<>(r.problems());
        List<String> events = new ArrayList<>(r.events());
        events.addAll(persons.restore(saved.state(), now, problems)); // each wearer's watch
        return new Restored(events, problems);
    }
}
