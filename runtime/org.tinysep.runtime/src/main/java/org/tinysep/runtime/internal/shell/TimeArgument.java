package org.tinysep.runtime.internal.shell;

import java.time.DateTimeException;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.OffsetDateTime;
import java.time.ZoneId;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Times typed in the shell: an ISO instant ({@code 2026-11-22T10:00:00Z}, or with an offset
 * {@code 2026-11-22T11:00+01:00}), a local date-time or date in the platform's time zone ({@code 2026-11-22T10:00},
 * {@code 2026-11-22 10:00:30}, {@code 2026-11-22}), {@code now}, or a time relative to now such as {@code -2h},
 * {@code -90s}, {@code -1d12h} (units {@code w d h m s}).
 */
final class TimeArgument {

    private static final Pattern RELATIVE = Pattern.compile("-((?:\\d+[wdhms])+)");
    private static final Pattern PART = Pattern.compile("(\\d+)([wdhms])");

    private TimeArgument() {
    }

    /** @throws IllegalArgumentException with the accepted forms when {@code text} is none of them */
    static Instant parse(String text, Instant now, ZoneId zone) {
        String t = text == null ? "" : text.strip();
        if (t.equalsIgnoreCase("now")) {
            return now;
        }
        Matcher m = RELATIVE.matcher(t);
        if (m.matches()) {
            return now.minus(duration(m.group(1)));
        }
        String iso = t.replace(' ', 'T');
        try {
            if (iso.endsWith("Z") || iso.endsWith("z")) {
                return Instant.parse(iso.toUpperCase());
            }
            if (iso.matches(".*T.*[+-]\\d\\d:?\\d\\d$")) {
                return OffsetDateTime.parse(iso).toInstant();
            }
            if (iso.contains("T")) {
                return LocalDateTime.parse(iso).atZone(zone).toInstant();
            }
            return LocalDate.parse(iso).atStartOfDay(zone).toInstant();
        } catch (DateTimeException | ArithmeticException e) {
            throw new IllegalArgumentException("'" + t + "' is not a time: give an ISO instant "
                    + "(2026-11-22T10:00:00Z), a local date-time (2026-11-22T10:00) or date (2026-11-22), now, "
                    + "or a time ago (-2h, -30m, -1d12h)");
        }
    }

    private static Duration duration(String parts) {
        Duration d = Duration.ZERO;
        Matcher p = PART.matcher(parts);
        while (p.find()) {
            long n = Long.parseLong(p.group(1));
            d = d.plus(switch (p.group(2)) {
                case "w" -> Duration.ofDays(7 * n);
                case "d" -> Duration.ofDays(n);
                case "h" -> Duration.ofHours(n);
                case "m" -> Duration.ofMinutes(n);
                default -> Duration.ofSeconds(n);
            });
        }
        return d;
    }
}
