package org.tinysep.inactivity.internal;

import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import org.tinysep.api.service.InactivityAlert;

/** The words of the help call: subject and body of the alert mail. */
final class AlertMail {

    private final DateTimeFormatter clock;
    private final DateTimeFormatter full;

    AlertMail(ZoneId zone) {
        this.clock = DateTimeFormatter.ofPattern("HH:mm").withZone(zone);
        this.full = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss z").withZone(zone);
    }

    String subject(InactivityAlert alert) {
        return "TinySEP: no activity in " + alert.roomName() + " since " + clock.format(alert.lastActivityAt());
    }

    String body(InactivityAlert alert) {
        return "Inactivity Recognition raised an alert: nobody has been active for longer than the limit of "
                + alert.roomName() + ".\n\n"
                + "Room: " + alert.roomName() + (alert.roomUid().isEmpty() ? "" : " (" + alert.roomUid() + ")") + "\n"
                + "Last activity: " + alert.lastActivity() + "\n"
                + "Last activity at: " + full.format(alert.lastActivityAt()) + "\n"
                + "Alert raised at: " + full.format(alert.raisedAt()) + "\n\n"
                + "Please check on the person. The alert clears by itself with the next activity in the flat.\n";
    }
}
