package org.tinysep.mqtt.board.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import org.tinysep.api.alert.AlertKind;

/** Times and durations in the words the board shows. */
final class BoardTime {

    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("HH:mm");
    private static final DateTimeFormatter DAY = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm");

    private BoardTime() {
    }

    /** @return "14:02" when on the same day as {@code now}, else "2026-11-24 14:02" */
    static String time(Instant at, Instant now, ZoneId zone) {
        if (at == null) {
            return "an unknown time";
        }
        boolean today = at.atZone(zone).toLocalDate().equals(now.atZone(zone).toLocalDate());
        return (today ? CLOCK : DAY).format(at.atZone(zone));
    }

    /** @return "45 s", "3 min", "5 h", "3 days" */
    static String duration(Duration d) {
        long s = Math.max(0, d.getSeconds());
        if (s < 120) {
            return s + " s";
        }
        if (s < 120 * 60) {
            return s / 60 + " min";
        }
        if (s < 72 * 3600) {
            return s / 3600 + " h";
        }
        return s / 86_400 + " days";
    }

    /**
     * @return what an alert of this kind (the flat's {@code AlertKind} name) is about, in the words the flat's MQTT
     *         bridge uses ({@link AlertKind#words()}); an unknown kind (a newer flat) as it came, lower case
     */
    static String kind(String kind) {
        if (kind == null || kind.isEmpty()) {
            return "alert";
        }
        for (AlertKind k : AlertKind.values()) {
            if (k.name().equals(kind)) {
                return k.words();
            }
        }
        return kind.toLowerCase(Locale.ROOT).replace('_', ' ');
    }
}
