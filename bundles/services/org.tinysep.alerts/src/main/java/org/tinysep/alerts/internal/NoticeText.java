package org.tinysep.alerts.internal;

import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import org.tinysep.api.log.EventEntry;

/** The words of a caregiver notice: what reduced the monitoring, where, since when, and what to do. */
final class NoticeText {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss z");

    private final ZoneId zone;

    NoticeText(ZoneId zone) {
        this.zone = zone;
    }

    /** @param signals at least one */
    String subject(List<EventEntry> signals) {
        EventEntry first = signals.get(0);
        String what = first.message().startsWith(NoticeFeed.REDUCED) ? "TinySEP watches less than it should: "
                : "TinySEP notice: a sensor node reports a different type: ";
        String detail = shorten(rest(first.message()), 90);
        return what + detail + (signals.size() > 1 ? " (and " + (signals.size() - 1) + " more)" : "");
    }

    String body(List<EventEntry> signals) {
        StringBuilder b = new StringBuilder("TinySEP noticed something that lowers how well the person is watched:\n\n");
        for (EventEntry e : signals) {
            b.append("  - since ").append(TIME.format(e.time().atZone(zone))).append(" (reported by ")
                    .append(e.origin().isEmpty() ? "the platform" : e.origin()).append("): ")
                    .append(rest(e.message())).append('\n');
        }
        b.append("\nWhat this means: until this is put right, TinySEP may not notice when the person needs help, ")
                .append("and nobody may be told.\n")
                .append("What to do: if you did not expect this, ask the person who installed TinySEP to check it ")
                .append("today. The details are in TinySEP's event log (web console: Events; shell: tinysep:events).\n")
                .append("This notice is sent once for each cause; it is not repeated. The daily summary lists it ")
                .append("again.\n");
        return b.toString();
    }

    /** @return the message without its contract prefix */
    static String rest(String message) {
        for (String p : List.of(NoticeFeed.REDUCED, NoticeFeed.MISMATCH)) {
            if (message.startsWith(p)) {
                return message.substring(p.length());
            }
        }
        return message;
    }

    private static String shorten(String s, int max) {
        if (s.length() <= max) {
            return s;
        }
        int end = Character.isHighSurrogate(s.charAt(max - 2)) ? max - 2 : max - 1; // never half a character
        return s.substring(0, end) + "...";
    }
}
