package org.tinysep.web.api.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tinysep.api.service.PersonWatch;

/**
 * What Inactivity Recognition knows of a person node's wearer ({@link PersonWatch}) for the
 * caregiver page, each also in plain words: whether the node is worn, its last movement, the room where the wearer
 * was last seen, and the wearer's own watch.
 */
final class PersonWatchWords {

    /** What the page shows for one node: {@code watch} is null when Inactivity Recognition does not watch its wearer. */
    record Source(boolean inactivityRunning, PersonWatch watch) {
    }

    private PersonWatchWords() {
    }

    /** @return {@code worn}, {@code wornWords}, {@code lastMovement}(Words), {@code lastRoom}(Words), {@code watch}(Words) */
    static Map<String, Object> json(String person, Source s, Instant now) {
        Map<String, Object> m = new LinkedHashMap<>();
        PersonWatch w = s.watch();
        m.put("worn", w == null ? null : w.worn());
        m.put("wornWords", wornWords(person, s, now));
        m.put("lastMovement", w == null ? null : w.lastMovement());
        m.put("lastMovementWords", w == null ? "not known" : PersonNodes.ago(Duration.between(w.lastMovement(), now)));
        m.put("lastRoom", w == null ? null : w.lastRoom().orElse(null));
        m.put("lastRoomWords", w == null ? "not known" : w.lastRoom().map(r -> "last seen in the " + r)
                .orElse("not seen in a room yet: no room sensor's activity has been counted as " + w.person() + "'s"));
        m.put("watch", w == null ? null : w.state());
        m.put("watchWords", watchWords(person, s));
        return m;
    }

    static String wornWords(String person, Source s, Instant now) {
        PersonWatch w = s.watch();
        if (w == null) {
            if (!s.inactivityRunning()) {
                return "not known: Inactivity Recognition is not running (it tells whether the node is worn)";
            }
            return person.isBlank() ? "not known: the node has no wearer's name, so its movement is nobody's activity"
                    : "not known yet: Inactivity Recognition has had no movement summary of this node yet";
        }
        if (w.worn()) {
            return "yes: its movement counts as " + w.person() + "'s activity";
        }
        return "seems not to be worn: it has not moved for " + span(Duration.between(w.lastMovement(), now))
                + " while the room sensors saw someone; until it moves again, " + w.person()
                + " is watched by the room sensors";
    }

    static String watchWords(String person, Source s) {
        PersonWatch w = s.watch();
        if (w == null) {
            return s.inactivityRunning() ? "not watched on their own yet" + (person.isBlank() ? "" : " (" + person
                    + "'s node has not reported to Inactivity Recognition yet)") : "not watched: Inactivity Recognition "
                    + "is not running";
        }
        String room = w.lastRoom().map(r -> "the " + r).orElse("the room where " + w.person() + " was last seen");
        return switch (w.state()) {
            case WATCHING -> "watching: an alert if " + w.person() + " is not active for longer than the limit of "
                    + room;
            case ALERT -> "ALERT: " + w.person() + " has not been active for longer than the limit of " + room
                    + "; help was called";
            case NOT_WATCHING -> "not watching: nobody seems to be home";
        };
    }

    /** @return e.g. "45 s", "12 min", "2 h 10 min" */
    static String span(Duration d) {
        long s = Math.max(0, d.getSeconds());
        if (s < 60) {
            return s + " s";
        }
        long min = s / 60;
        return min < 60 ? min + " min" : min / 60 + " h" + (min % 60 == 0 ? "" : " " + min % 60 + " min");
    }
}
