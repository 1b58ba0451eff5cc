package org.tinysep.mailmanager.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** The plain words of the Mail Manager's event-log entries and status details. */
final class MailText {

    /** Same zone as the event log's time stamps (UTC), so "retrying at" can be compared with them. */
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss 'UTC'")
            .withZone(ZoneOffset.UTC);

    private MailText() {
    }

    /** @return e.g. {@code 13:42:05 UTC} */
    static String time(Instant at) {
        return TIME.format(at);
    }

    /** @return e.g. {@code 45 s}, {@code 12 min 5 s}, {@code 24 h 0 min} */
    static String duration(Duration d) {
        long s = Math.max(0, d.getSeconds());
        if (s < 60) {
            return s + " s";
        }
        if (s < 3600) {
            return s / 60 + " min " + s % 60 + " s";
        }
        return s / 3600 + " h " + s % 3600 / 60 + " min";
    }

    /** @return {@code mail "subject"} */
    static String mail(MailMessage m) {
        return "mail \"" + m.subject() + "\"";
    }

    /**
     * @param replies recipient to reply
     * @return the recipients grouped by reply, e.g. {@code a@x, b@y (452 4.5.3 too many recipients to RCPT)}
     */
    static String replies(Map<String, String> replies) {
        return String.join("; ", grouped(replies, (to, reply) -> to + " (" + reply + ")"));
    }

    /** @return e.g. {@code mail "S" to b@y: delivery failed temporarily (452 ...), retrying at 13:42:05 UTC (in 10 s)} */
    static String retrying(MailMessage m, Map<String, String> replies, Instant at, long inSeconds) {
        return mail(m) + " " + String.join("; ", grouped(replies, (to, reply) -> "to " + to
                + ": delivery failed temporarily (" + reply + "), retrying at " + time(at) + " (in " + inSeconds
                + " s)"));
    }

    /** @return e.g. {@code mail "S" NOT delivered to b@y: given up after 24 h 0 min of retrying (last reply: ...)} */
    static String failed(MailMessage m, Map<String, String> replies, String how, String replyLabel) {
        return mail(m) + " " + String.join("; ", grouped(replies, (to, reply) -> "NOT delivered to " + to + ": "
                + how + " (" + replyLabel + reply + ")"));
    }

    private static List<String> grouped(Map<String, String> replies,
            java.util.function.BiFunction<String, String, String> line) {
        Map<String, List<String>> byReply = new LinkedHashMap<>();
        replies.forEach((to, reply) -> byReply.computeIfAbsent(reply, k -> new ArrayList<>()).add(to));
        List<String> parts = new ArrayList<>();
        byReply.forEach((reply, to) -> parts.add(line.apply(String.join(", ", to), reply)));
        return parts;
    }
}
