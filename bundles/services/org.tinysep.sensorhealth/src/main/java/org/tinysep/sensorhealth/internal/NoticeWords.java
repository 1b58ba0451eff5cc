package org.tinysep.sensorhealth.internal;

import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.stream.Collectors;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.sensorhealth.internal.Notices.Kind;
import org.tinysep.sensorhealth.internal.Notices.Notice;

/**
 * The words of notices. Subjects start with "TinySEP notice:" so that they are told apart from an inactivity alert
 * at a glance, and every body says that this is a notice, not an alarm.
 */
final class NoticeWords {

    static final String PREFIX = "TinySEP notice: ";

    private final DateTimeFormatter clock;
    private final DateTimeFormatter full;

    NoticeWords(ZoneId zone) {
        this.clock = DateTimeFormatter.ofPattern("HH:mm").withZone(zone);
        this.full = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss z").withZone(zone);
    }

    /** @return "sensor offline in Bathroom since 09:12" and the like */
    String line(Notice n) {
        String where = where(n.sensor());
        return switch (n.kind()) {
            case OFFLINE -> "sensor offline " + where + " since " + clock.format(n.since());
            case BACK -> "sensor back online " + where;
            case LOW_BATTERY -> "low battery " + where;
        };
    }

    private static String where(SensorHealth s) {
        return s.roomName() != null ? "in " + s.roomName() : "(" + s.name() + ", not placed in a room)";
    }

    String subject(List<Notice> notices) {
        if (notices.size() == 1) {
            return PREFIX + line(notices.get(0));
        }
        return PREFIX + notices.size() + " sensor changes: " + notices.stream().map(this::line)
                .collect(Collectors.joining("; "));
    }

    String body(List<Notice> notices) {
        StringBuilder b = new StringBuilder("This is a notice about the sensors, not an alarm: nobody needs help "
                + "because of it, but someone should look at the sensor soon.\n\n");
        for (Notice n : notices) {
            SensorHealth s = n.sensor();
            b.append("- ").append(Character.toUpperCase(line(n).charAt(0))).append(line(n).substring(1)).append(": ")
                    .append(s.name()).append(" (node ").append(s.node().nodeAddress()).append(", ")
                    .append(String.join("/", s.node().nodeTypes())).append(").\n  ");
            switch (n.kind()) {
                case OFFLINE -> b.append("Its last report came at ").append(full.format(n.since()))
                        .append("; it promises one every ").append(s.node().reportInterval().toSeconds())
                        .append(" s. Its battery may be flat, it may be out of radio range or broken. While it is "
                                + "silent, TinySEP cannot see what happens there.\n");
                case BACK -> b.append("It reports again; TinySEP sees that room again.\n");
                case LOW_BATTERY -> b.append("Its battery reads ").append(s.node().batteryMillivolts())
                        .append(" mV. Please replace or recharge it before the sensor stops reporting.\n");
                default -> { }
            }
        }
        if (notices.stream().anyMatch(n -> n.kind() == Kind.OFFLINE)) {
            b.append("\nA sensor that stays silent also means an inactivity alert for its room cannot be "
                    + "raised.\n");
        }
        return b.toString();
    }
}
