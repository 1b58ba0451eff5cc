package org.tinysep.alerts.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import org.tinysep.api.alert.Alert;

/** The plain words of alert messages and event-log entries. */
final class AlertText {

    private final DateTimeFormatter clock;
    private final DateTimeFormatter full;

    AlertText(ZoneId zone) {
        this.clock = DateTimeFormatter.ofPattern("HH:mm").withZone(zone);
        this.full = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss z").withZone(zone);
    }

    String time(Instant at) {
        return clock.format(at);
    }

    String fullTime(Instant at) {
        return full.format(at);
    }

    static String minutes(Duration d) {
        long m = Math.max(0, d.toMinutes());
        return m < 120 ? m + " min" : m / 60 + " h " + m % 60 + " min";
    }

    /** @return e.g. "carer@x, doctor@y", or "the Mail Manager's recipients" */
    static String who(List<String> to) {
        return to.isEmpty() ? "the Mail Manager's recipients" : String.join(", ", to);
    }

    String firstSubject(Alert a) {
        return a.subject() + " [alert " + a.id() + "]";
    }

    String repeatSubject(Alert a, Instant now) {
        return "REPEATED, not acknowledged for " + minutes(Duration.between(first(a), now)) + ": " + a.subject()
                + " [alert " + a.id() + "]";
    }

    String escalationSubject(Alert a, Instant now) {
        return "ESCALATED, not acknowledged for " + minutes(Duration.between(first(a), now)) + ": " + a.subject()
                + " [alert " + a.id() + "]";
    }

    String allClearSubject(Alert a) {
        return "All clear: " + a.subject() + " [alert " + a.id() + "]";
    }

    /** The body of the first message, repeats and escalations: the detector's text and how to acknowledge. */
    String body(Alert a, List<String> toldSoFar, Instant now) {
        return a.text().strip() + "\n\n"
                + "Alert " + a.id() + " was raised at " + fullTime(a.raisedAt()) + " and is not acknowledged yet"
                + (a.notifications().isEmpty() ? "" : " (told so far: " + who(toldSoFar) + ")") + ".\n"
                + "If you take care of it, acknowledge it so that it is not repeated or passed on: type\n"
                + "    tinysep:ack " + a.id() + " \"your name\"\n"
                + "in the TinySEP shell. Until then it is repeated and passed on to the next contact.\n";
    }

    String allClearBody(Alert a, String why) {
        return "All clear for alert " + a.id() + " (" + a.subject() + ", raised at " + fullTime(a.raisedAt())
                + "): " + why + ".\n\nNobody needs to come any more. The alert was:\n\n" + a.text().strip() + "\n";
    }

    private static Instant first(Alert a) {
        return a.notifications().isEmpty() ? a.raisedAt() : a.notifications().get(0).at();
    }
}
