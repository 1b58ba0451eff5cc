package org.tinysep.simulator.replay;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeParseException;
import java.util.List;

/** Shared helpers of the plain CSV formats: no quoting, so fields must not contain commas, quotes or line breaks. */
final class Csv {

    private Csv() {
    }

    /** Takes one row of a file: its fields and its line number (from 1). */
    @FunctionalInterface
    interface Row {
        void accept(String[] fields, int lineNo) throws ReplayFormatException;
    }

    /**
     * Checks that the first line is {@code header} (after a byte-order mark), then hands each non-blank row's fields
     * (as many as the header has, trimmed) to {@code row}, in file order.
     *
     * @throws ReplayFormatException naming {@code file} and the line, for a wrong header or a row of another width
     */
    static void rows(List<String> lines, String header, String file, Row row) throws ReplayFormatException {
        if (lines.isEmpty() || !stripBom(lines.get(0)).strip().equals(header)) {
            throw new ReplayFormatException(file, 1, "expected the header '" + header + "'");
        }
        int count = header.split(",", -1).length;
        for (int i = 1; i < lines.size(); i++) {
            if (!lines.get(i).isBlank()) {
                row.accept(fields(lines.get(i), count, header, file, i + 1), i + 1);
            }
        }
    }

    /** @return a UTF-8 writer of {@code file} (replaced) that has written {@code header} and a line feed */
    static BufferedWriter writer(Path file, String header) throws IOException {
        BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        try {
            w.write(header);
            w.write('\n');
            return w;
        } catch (IOException | RuntimeException e) {
            w.close();
            throw e;
        }
    }

    static String stripBom(String s) {
        return s.startsWith("\uFEFF") ? s.substring(1) : s;
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
