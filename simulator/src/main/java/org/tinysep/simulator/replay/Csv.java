package org.tinysep.simulator.replay;

import java.time.LocalDateTime;
import java.time.format.DateTimeParseException;

/** Shared helpers of the plain CSV formats: no quoting, so fields must not contain commas, quotes or line breaks. */
final class Csv {

    private Csv() {
    }

    /** @return the row's fields (exactly {@code count}, trimmed) or throws naming file and line */
    static String[] fields(String line, int count, String header, String file, int lineNo)
            throws ReplayFormatException {
        String[] f = line.split(",", -1);
        if (f.length != count) {
            throw new ReplayFormatException(file, lineNo, "expected " + count + " comma-separated fields ("
                    + header + "), found " + f.length);
        }
        for (int i = 0; i < f.length; i++) {
            f[i] = f[i].strip();
        }
        return f;
    }

    static LocalDateTime time(String text, String file, int lineNo) throws ReplayFormatException {
        try {
            return LocalDateTime.parse(text);
        } catch (DateTimeParseException e) {
            throw new ReplayFormatException(file, lineNo, "bad time '" + text
                    + "', expected local ISO-8601 without zone, e.g. 2011-11-28T02:27:59 or 2011-11-28T02:27:59.250");
        }
    }

    /** @return the time as ISO-8601 with seconds always written, e.g. 2011-11-28T02:28:00 */
    static String format(LocalDateTime time) {
        return java.time.format.DateTimeFormatter.ISO_LOCAL_DATE_TIME.format(time);
    }

    /** @return the field unchanged, or throws if it cannot be written without quoting */
    static String check(String field, String what) {
        if (field.contains(",") || field.contains("\"") || field.contains("\n") || field.contains("\r")
                || !field.equals(field.strip())) {
            throw new IllegalArgumentException(what + " '" + field
                    + "' cannot be written: commas, quotes, line breaks and outer spaces are not allowed");
        }
        return field;
    }
}
