package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Map;
import java.util.Optional;

/**
 * The platform's sign of life in the state folder, {@value #FILE}: {@code pid}, {@code started}, {@code alive} (the
 * last time the liveness probe passed) and {@code state} ({@code STARTING}, {@code RUNNING}, {@code STOPPED} after a
 * clean stop). The supervisor reads it to tell a hung platform from a live one; the next start reads it to tell a
 * crash from a clean stop.
 */
final class HeartbeatFile {

    static final String FILE = "heartbeat.properties";

    /** One reading of the file. */
    record Beat(long pid, Instant alive, String state) {
    }

    private final Path file;
    private final long pid = ProcessHandle.current().pid();
    private final Instant started = Instant.now();

    HeartbeatFile(Path var) {
        this.file = var.resolve(FILE);
    }

    void write(String state, Instant alive) throws IOException {
        StateFile.write(file, Map.of("pid", Long.toString(pid), "started", started.toString(),
                "alive", alive.toString(), "state", state), false);
    }

    static Optional<Beat> read(Path var) {
        return StateFile.read(var.resolve(FILE)).flatMap(m -> {
            try {
                return Optional.of(new Beat(Long.parseLong(m.get("pid")), Instant.parse(m.get("alive")),
                        m.get("state")));
            } catch (RuntimeException e) {
                return Optional.empty();
            }
        });
    }

    /**
     * At start, before the framework: completes a note the supervisor left (cause and time) with this restart's
     * time and sentence; without one, when the last run's heartbeat says it never stopped cleanly, leaves a note of
     * its own. A note completed earlier and not yet mailed is left as it is.
     *
     * @return the note's sentence, if this start is a restart after a failure
     */
    static Optional<String> noteRestart(Path var, Instant now, java.time.ZoneId zone) throws IOException {
        boolean completed = StateFile.read(var.resolve(RestartNote.FILE)).map(m -> m.containsKey("message"))
                .orElse(false);
        Optional<RestartNote> note = completed ? Optional.empty() : RestartNote.read(var);
        if (note.isEmpty()) {
            note = read(var).filter(b -> !"STOPPED".equals(b.state()))
                    .map(b -> new RestartNote(RestartNote.UNCLEAN, b.alive()));
        }
        if (note.isEmpty()) {
            return Optional.empty();
        }
        note.get().complete(var, now, zone);
        return Optional.of(note.get().sentence(now, zone));
    }
}
