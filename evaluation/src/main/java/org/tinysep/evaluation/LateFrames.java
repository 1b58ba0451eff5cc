package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

/**
 * After a lock-step run: how many of a node's frames the platform stamped with another instant than the one they
 * were played at (its packet log's RECEIVED lines against the played instants). A frame is stamped late when the
 * platform had not handled it before the next TICK (the pace was too short for the machine's load); a late summary
 * or a burst given up can change what Fall Detection decides, so the run says how many there were.
 */
final class LateFrames {

    private final Set<Instant> played = new HashSet<>();
    private int frames;

    /** The instants frames were played at. */
    void played(List<Instant> instants) {
        played.addAll(instants);
        frames += instants.size();
    }

    int played() {
        return frames;
    }

    /**
     * @return how many RECEIVED lines of {@code node} stamped from {@code from} on, in the packet logs under
     *         {@code var/log}, are not at a played instant
     */
    int late(Path var, String node, Instant from) throws IOException {
        Path dir = var.resolve("log");
        if (!Files.isDirectory(dir)) {
            return 0;
        }
        List<Path> logs;
        try (Stream<Path> s = Files.list(dir)) {
            logs = s.filter(p -> p.getFileName().toString().matches("packets-\\d+\\.log")).sorted().toList();
        }
        int late = 0;
        for (Path p : logs) {
            for (String line : Files.readAllLines(p)) {
                String[] f = line.split("\t");
                if (f.length < 4 || !f[2].equals("RECEIVED") || !f[3].toLowerCase().contains(node.toLowerCase())) {
                    continue;
                }
                try {
                    Instant at = Instant.parse(f[0]);
                    if (!at.isBefore(from) && !played.contains(at)) {
                        late++;
                    }
                } catch (DateTimeParseException e) {
                    late++;
                }
            }
        }
        return late;
    }
}
