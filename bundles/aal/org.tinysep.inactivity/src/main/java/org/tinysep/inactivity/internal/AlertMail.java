package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import org.tinysep.api.health.UnmonitoredRoom;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.inactivity.internal.learn.Amounts;

/** The words of the help call: subject and body of the alert mail. */
final class AlertMail {

    private final DateTimeFormatter clock;
    private final DateTimeFormatter full;
    private final Supplier<List<UnmonitoredRoom>> unwatched;

    AlertMail(ZoneId zone) {
        this(zone, List::of);
    }

    /** @param unwatched the rooms none of whose sensors can be heard now (Sensor Health; empty without it) */
    AlertMail(ZoneId zone, Supplier<List<UnmonitoredRoom>> unwatched) {
        this.clock = DateTimeFormatter.ofPattern("HH:mm").withZone(zone);
        this.full = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss z").withZone(zone);
        this.unwatched = unwatched;
    }

    /**
     * @return e.g. "Bathroom (no sensor heard since 09:12)", the rooms that could not be watched, joined by ", ";
     *         empty when every room can be heard
     */
    String unwatchedRooms() {
        List<UnmonitoredRoom> rooms;
        try {
            rooms = unwatched.get();
        } catch (RuntimeException e) { // Sensor Health going away: the alert goes out without this line
            return "";
        }
        return rooms.stream().map(r -> r.roomName() + (r.since() == null ? " (no sensor heard)"
                : " (no sensor heard since " + clock.format(r.since()) + ")")).collect(Collectors.joining(", "));
    }

    String subject(InactivityAlert alert) {
        return "TinySEP: no activity in " + alert.roomName() + " since " + clock.format(alert.lastActivityAt());
    }

    /**
     * @return the subject, and for an alert that fell due during {@code outage} (may be null) the words
     *         "(Inactivity Recognition was not running from 14:20 to 15:10; this alert is late)"
     */
    String subject(InactivityAlert alert, Outage outage) {
        return subject(alert) + (outage != null && outage.delayed(alert) ? " (" + late(outage) + ")" : "");
    }

    private String late(Outage outage) {
        return "Inactivity Recognition was not running from " + clock.format(outage.from()) + " to "
                + clock.format(outage.to()) + "; this alert is late";
    }

    /** @return a time for the event log, e.g. "2026-11-22 14:01:00 UTC" */
    String time(Instant at) {
        return full.format(at);
    }

    String body(InactivityAlert alert, Outage outage) {
        String body = body(alert);
        if (outage == null || !outage.delayed(alert)) {
            return body;
        }
        return body.replace("\n\nPlease check", "\nIt fell due at " + full.format(alert.raisedAt())
                + ", while Inactivity Recognition was not running (from " + full.format(outage.from()) + " to "
                + full.format(outage.to()) + "): this alert is late.\n\nPlease check");
    }

    /** @return for the event log: "; quiet for 1 h 10 min; usually at most ..." (empty without explanation) */
    String why(InactivityAlert alert) {
        String rooms = unwatchedRooms();
        return (alert.explanation().isEmpty() ? ""
                : "; quiet for " + quiet(alert) + " after " + alert.lastActivity() + "; " + alert.explanation())
                + (rooms.isEmpty() ? "" : "; could not be watched: " + rooms);
    }

    private static String quiet(InactivityAlert alert) {
        return Amounts.duration(Duration.between(alert.lastActivityAt(), alert.raisedAt()));
    }

    private String unwatchedLine() {
        String rooms = unwatchedRooms();
        return rooms.isEmpty() ? "" : "Could not be watched: " + rooms + ". Sensors there are offline (battery or "
                + "radio), so activity there would not have been seen.\n";
    }

    String body(InactivityAlert alert) {
        return "Inactivity Recognition raised an alert: nobody has been active for longer than the limit of "
                + alert.roomName() + ".\n\n"
                + "Room: " + alert.roomName() + (alert.roomUid().isEmpty() ? "" : " (" + alert.roomUid() + ")") + "\n"
                + "Last activity: " + alert.lastActivity() + "\n"
                + "Last activity at: " + full.format(alert.lastActivityAt()) + "\n"
                + "Quiet for: " + quiet(alert) + "\n"
                + (alert.explanation().isEmpty() ? "" : "Why this is unusual: " + alert.explanation() + "\n")
                + unwatchedLine()
                + "Alert raised at: " + full.format(alert.raisedAt()) + "\n\n"
                + "Please check on the person. The alert clears by itself with the next activity in the flat.\n";
    }
}
