package org.tinysep.simulator.replay;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Reads the Ordonez ADL data set (Ordonez, de Toledo, Sanchis, Sensors 2013, 13, 5460-5477): CRLF text, two header
 * lines, columns separated by irregular runs of tabs and spaces. Sensor rows {@code start end location type place}
 * become two {@link SensorEvent}s each (ON at start, OFF at end); ADL rows {@code start end activity} become
 * {@link Label}s. Blank lines are skipped; anything else malformed is a {@link ReplayFormatException} naming file
 * and line.
 *
 * <p>Sensor identity: the Location column, unless the same Location occurs in several Places in the file (Home B has
 * three PIR sensors all called {@code Door}), then {@code Location Place}, e.g. {@code Door Kitchen}.
 */
public final class OrdonezReader {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss");

    private OrdonezReader() {
    }

    /** One sensor activation interval as read. */
    private record Row(int line, LocalDateTime start, LocalDateTime end, String location, Kind kind, String place) {
    }

    /**
     * @param file an {@code Ordonez?_Sensors.txt} file
     * @return the events, time-ordered (stable: file order among equal times, so ON precedes OFF of one interval)
     * @throws IOException if the file cannot be read
     * @throws ReplayFormatException if a row is malformed
     */
    public static List<SensorEvent> readSensors(Path file) throws IOException, ReplayFormatException {
        return parseSensors(read(file), file.getFileName().toString());
    }

    /**
     * @param file an {@code Ordonez?_ADLs.txt} file
     * @return the labels in file order, resident empty
     * @throws IOException if the file cannot be read
     * @throws ReplayFormatException if a row is malformed
     */
    public static List<Label> readLabels(Path file) throws IOException, ReplayFormatException {
        return parseLabels(read(file), file.getFileName().toString());
    }

    /** Parses the lines of a sensor file (CRs allowed); {@code name} is used in messages. */
    static List<SensorEvent> parseSensors(List<String> lines, String name) throws ReplayFormatException {
        List<Row> rows = new ArrayList<>();
        for (int i = checkHeader(lines, name); i < lines.size(); i++) {
            String[] t = tokens(lines.get(i));
            if (t.length == 0) {
                continue;
            }
            if (t.length < 7) {
                throw new ReplayFormatException(name, i + 1, "expected 'start end location type place' "
                        + "(7 fields, times as yyyy-MM-dd HH:mm:ss), found " + t.length + " fields");
            }
            LocalDateTime start = time(t[0], t[1], name, i + 1);
            LocalDateTime end = time(t[2], t[3], name, i + 1);
            if (end.isBefore(start)) {
                throw new ReplayFormatException(name, i + 1,
                        "interval ends (" + end + ") before it starts (" + start + ")");
            }
            String location = String.join(" ", List.of(t).subList(4, t.length - 2));
            rows.add(new Row(i + 1, start, end, location, kind(t[t.length - 2], name, i + 1), t[t.length - 1]));
        }
        Map<String, Set<String>> places = new HashMap<>();
        rows.forEach(r -> places.computeIfAbsent(r.location(), k -> new HashSet<>()).add(r.place()));
        List<SensorEvent> events = new ArrayList<>(rows.size() * 2);
        for (Row r : rows) {
            String sensor = places.get(r.location()).size() > 1 ? r.location() + " " + r.place() : r.location();
            events.add(new SensorEvent(r.start(), sensor, r.place(), r.kind(), true));
            events.add(new SensorEvent(r.end(), sensor, r.place(), r.kind(), false));
        }
        events.sort(Comparator.comparing(SensorEvent::time));
        return events;
    }

    /** Parses the lines of an ADL file (CRs allowed); {@code name} is used in messages. */
    static List<Label> parseLabels(List<String> lines, String name) throws ReplayFormatException {
        List<Label> labels = new ArrayList<>();
        for (int i = checkHeader(lines, name); i < lines.size(); i++) {
            String[] t = tokens(lines.get(i));
            if (t.length == 0) {
                continue;
            }
            if (t.length < 5) {
                throw new ReplayFormatException(name, i + 1, "expected 'start end activity' "
                        + "(times as yyyy-MM-dd HH:mm:ss), found " + t.length + " fields");
            }
            labels.add(new Label(time(t[0], t[1], name, i + 1), time(t[2], t[3], name, i + 1),
                    String.join(" ", List.of(t).subList(4, t.length)), ""));
        }
        return labels;
    }

    private static int checkHeader(List<String> lines, String name) throws ReplayFormatException {
        if (lines.size() < 2 || !lines.get(0).trim().startsWith("Start time") || !lines.get(1).trim().startsWith("-")) {
            throw new ReplayFormatException(name, 1,
                    "not an Ordonez file: expected a 'Start time ...' header line and a '-----' line");
        }
        return 2;
    }

    private static String[] tokens(String line) {
        String s = line.strip();
        return s.isEmpty() ? new String[0] : s.split("[\\s]+");
    }

    private static LocalDateTime time(String date, String clock, String name, int line) throws ReplayFormatException {
        try {
            return LocalDateTime.parse(date + " " + clock, TIME);
        } catch (DateTimeParseException e) {
            throw new ReplayFormatException(name, line, "bad time '" + date + " " + clock
                    + "', expected yyyy-MM-dd HH:mm:ss");
        }
    }

    private static Kind kind(String type, String name, int line) throws ReplayFormatException {
        switch (type) {
            case "PIR": return Kind.MOTION;
            case "Magnetic": return Kind.DOOR;
            case "Pressure": return Kind.PRESSURE;
            case "Flush": return Kind.FLUSH;
            case "Electric": return Kind.ELECTRIC;
            default:
                throw new ReplayFormatException(name, line, "unknown sensor type '" + type
                        + "', expected PIR, Magnetic, Pressure, Flush or Electric");
        }
    }

    private static List<String> read(Path file) throws IOException {
        return Files.readAllLines(file, StandardCharsets.ISO_8859_1);
    }
}
