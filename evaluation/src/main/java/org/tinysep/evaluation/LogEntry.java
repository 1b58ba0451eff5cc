package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * One line of the platform's event-log files ({@code <state folder>/log/events-*.log}, docs/logs.md):
 * {@code <time>\t<sequence>\t<KIND>\t<origin>\t<message>}. The harness reads what the platform wrote, never a copy of
 * its logic.
 *
 * @param time     platform time of the entry (virtual time in lock-step)
 * @param sequence the log's sequence number (numbering continues across restarts)
 * @param kind     the EventKind name
 * @param message  the message, escapes kept as written
 */
record LogEntry(Instant time, long sequence, String kind, String message) {

    /** @return every readable entry of the event-log files in {@code var/log}, in sequence order */
    static List<LogEntry> read(Path var) throws IOException {
        Path dir = var.resolve("log");
        List<LogEntry> out = new ArrayList<>();
        if (!Files.isDirectory(dir)) {
            return out;
        }
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(f -> f.getFileName().toString().matches("events-\\d+\\.log")).sorted().toList();
        }
        for (Path f : files) {
            for (String line : Files.readAllLines(f)) {
                String[] p = line.split("\t", 5);
                if (p.length < 5) {
                    continue; // damaged or being written
                }
                try {
                    out.add(new LogEntry(Instant.parse(p[0]), Long.parseLong(p[1]), p[2], p[4]));
                } catch (DateTimeParseException | NumberFormatException e) {
                    // a damaged line: the platform skips it too
                }
            }
        }
        out.sort(Comparator.comparingLong(LogEntry::sequence));
        return out;
    }

    /** @return the highest sequence number in the files, 0 without any */
    static long lastSequence(Path var) throws IOException {
        List<LogEntry> all = read(var);
        return all.isEmpty() ? 0 : all.get(all.size() - 1).sequence();
    }
}
