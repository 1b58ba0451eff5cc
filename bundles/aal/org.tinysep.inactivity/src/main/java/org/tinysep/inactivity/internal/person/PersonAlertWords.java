package org.tinysep.inactivity.internal.person;

import java.time.Duration;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.time.Instant;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.inactivity.internal.learn.Amounts;

/** The words of a wearer's own inactivity alert: subject and body, and its line in the event log. */
public final class PersonAlertWords {

    private final DateTimeFormatter clock;
    private final DateTimeFormatter full;

    public PersonAlertWords(ZoneId zone) {
        this.clock = DateTimeFormatter.ofPattern("HH:mm").withZone(zone);
        this.full = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss z").withZone(zone);
    }

    /** @return e.g. "10:12" */
    public String time(Instant at) {
        return clock.format(at);
    }

    /** @return e.g. "TinySEP: Anna has not been active since 10:12 (last seen in Kitchen)" */
    public String subject(String person, InactivityAlert alert) {
        return "TinySEP: " + person + " has not been active since " + clock.format(alert.lastActivityAt())
                + (alert.roomName().isEmpty() || alert.roomUid().isEmpty() ? "" : " (last seen in " + alert.roomName()
                        + ")");
    }

    /** @return for the event log: how long, after what, why that limit, and who explained the room activity */
    public String why(Wearers.View w, InactivityAlert alert) {
        return "; " + w.person() + "'s pendant " + still(w, alert) + "; last activity: " + alert.lastActivity()
                + (alert.explanation().isEmpty() ? "" : "; " + alert.explanation()) + meanwhile(w);
    }

    private String still(Wearers.View w, InactivityAlert alert) {
        return (w.everMoved() ? "has been still since " : "has not moved since it was first heard at ")
                + clock.format(w.lastMovement()) + " ("
                + Amounts.duration(Duration.between(w.lastMovement(), alert.raisedAt())) + ")";
    }

    private static String meanwhile(Wearers.View w) {
        return w.explained() == 0 ? "" : "; meanwhile the room sensors saw activity " + w.explained() + " time"
                + (w.explained() == 1 ? "" : "s") + ", each while the node of " + String.join(" or ", w.explainedBy())
                + " was moving, so it was not counted as " + w.person() + "'s";
    }

    public String body(Wearers.View w, InactivityAlert alert) {
        String room = alert.roomUid().isEmpty() ? "not known (no room activity was counted as " + w.person()
                + "'s yet)" : alert.roomName() + " (" + alert.roomUid() + ")";
        String m = meanwhile(w);
        return "Inactivity Recognition raised an alert for " + w.person() + ": " + w.person() + "'s pendant has "
                + "not moved, and nothing the room sensors saw could have been " + w.person() + ", for longer than "
                + "the limit of the room where " + w.person() + " was last seen.\n\n"
                + "Person: " + w.person() + " (person node " + w.nodeUid() + ")\n"
                + "Last seen in: " + room + "\n"
                + "Pendant: " + still(w, alert) + "\n"
                + "Last activity: " + alert.lastActivity() + " at " + full.format(alert.lastActivityAt()) + "\n"
                + "Quiet for: " + Amounts.duration(Duration.between(alert.lastActivityAt(), alert.raisedAt())) + "\n"
                + (alert.explanation().isEmpty() ? "" : "Why this is unusual: " + alert.explanation() + "\n")
                + (m.isEmpty() ? "" : "M" + m.substring(3) + ".\n")
                + "Alert raised at: " + full.format(alert.raisedAt()) + "\n\n"
                + "Please check on " + w.person() + ". The alert clears by itself when " + w.person()
                + "'s pendant moves again.\n";
    }
}
