package org.tinysep.simulator.replay;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;

/**
 * The generic event log {@code events.csv} (simulator/README-replay.md "Generic: events.csv and labels.csv"): header
 * {@value #HEADER}; one row per state change in time order; time local ISO-8601 without zone (fractional seconds
 * optional); kind one of motion, door, pressure, flush, electric, other; value ON/OFF or OPEN/CLOSE.
 */
public final class EventsCsv {

    /** The exact header line. */
    public static final String HEADER = "time_iso,sensor,room,kind,value";

    private EventsCsv() {
    }

    /**
     * @param file events.csv (UTF-8; CRLF or LF; blank lines skipped)
     * @return the events in file order
     * @throws IOException if the file cannot be read
     * @throws ReplayFormatException naming file and line for a wrong header, a malformed row or a row earlier than
     *                               the one before it
     */
    public static List<SensorEvent> read(Path file) throws IOException, ReplayFormatException {
        return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.getFileName().toString());
    }

    static List<SensorEvent> parse(List<String> lines, String name) throws ReplayFormatException {
        List<SensorEvent> events = new ArrayList<>();
        Csv.rows(lines, HEADER, name, (f, line) -> {
            LocalDateTime time = Csv.time(f[0], name, line);
            LocalDateTime previous = events.isEmpty() ? null : events.get(events.size() - 1).time();
            if (previous != null && time.isBefore(previous)) {
                throw new ReplayFormatException(name, line, "time " + f[0] + " is earlier than the row before ("
                        + previous + "); rows must be in time order");
            }
            if (f[1].isEmpty()) {
                throw new ReplayFormatException(name, line, "sensor name is empty");
            }
            Kind kind;
            try {
                kind = Kind.parse(f[3]);
            } catch (IllegalArgumentException e) {
                throw new ReplayFormatException(name, line, e.getMessage());
            }
            events.add(new SensorEvent(time, f[1], f[2], kind, value(f[4], name, line)));
        });
        return events;
    }

    /**
     * Writes events as events.csv (LF line ends). Door events are written OPEN/CLOSE, all others ON/OFF.
     *
     * @param events events in time order
     * @param file   target file, replaced
     * @throws IOException if writing fails
     * @throws IllegalArgumentException if events are out of time order or a name cannot be written unquoted
     */
    public static void write(List<SensorEvent> events, Path file) throws IOException {
        try (BufferedWriter w = Csv.writer(file, HEADER)) {
            LocalDateTime previous = null;
            for (SensorEvent e : events) {
                if (previous != null && e.time().isBefore(previous)) {
                    throw new IllegalArgumentException("events out of time order at " + e);
                }
                previous = e.time();
                String value = e.kind() == Kind.DOOR ? (e.on() ? "OPEN" : "CLOSE") : (e.on() ? "ON" : "OFF");
                w.write(Csv.format(e.time()) + "," + Csv.check(e.sensor(), "sensor") + ","
                        + Csv.check(e.room(), "room") + ","
                        + e.kind().csvName() + "," + value + "\n");
            }
        }
    }

    private static boolean value(String v, String name, int line) throws ReplayFormatException {
        switch (v.toUpperCase(java.util.Locale.ROOT)) {
            case "ON": case "OPEN": return true;
            case "OFF": case "CLOSE": return false;
            default:
                throw new ReplayFormatException(name, line, "bad value '" + v + "', expected ON, OFF, OPEN or CLOSE");
        }
    }
}
