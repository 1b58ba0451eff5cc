package org.tinysep.web.api.internal;

import java.util.List;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;

/**
 * Which channel reached whom, for the caregiver page: one sentence per message sent about an alert,
 * e.g. "escalation to Otto by push: delivered (taken by the push server ntfy.example.org for topic otto-topic)".
 */
final class AlertReach {

    private AlertReach() {
    }

    static List<String> lines(Alert a) {
        return a.notifications().stream().map(AlertReach::line).toList();
    }

    static String line(Notification n) {
        String step = switch (n.step()) {
            case FIRST -> "first message";
            case REPEAT -> "repeat";
            case ESCALATION -> "escalation";
            case ALL_CLEAR -> "all clear";
        };
        String channel = switch (n.channel()) {
            case Notification.MAIL -> "e-mail";
            case "sms" -> "SMS";
            default -> n.channel();
        };
        String outcome = switch (n.outcome()) {
            case QUEUED -> "on its way";
            case SENT -> "delivered";
            case RETRYING -> "not delivered yet, being tried again";
            case FAILED -> "NOT delivered";
            case LOGGED_ONLY -> "only written to the log (no mail server set up)";
            case UNKNOWN -> "outcome unknown";
        };
        String who = n.to().isEmpty() ? "the Mail Manager's recipients" : String.join(", ", n.to());
        return step + " to " + who + " by " + channel + ": " + outcome + (n.detail().isEmpty() ? "" : " ("
                + n.detail() + ")");
    }
}
