package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * What the next platform start must tell the caregivers: why the last run ended without a clean stop and when.
 * The supervisor writes it when it restarts a platform that stopped responding or ended with an error; the launcher
 * writes it itself when it finds the last run's heartbeat still {@code RUNNING} (a crash, a power cut, a SIGKILL)
 * and no note yet. File {@value #FILE} in the state folder; the runtime's restart reporter records the sentence in
 * the event log, mails it through the Mail Manager and then deletes the file.
 *
 * @param cause what happened, in plain words, ending where a time fits ("stopped responding")
 * @param at    when it happened (the last sign of life for a hang or a crash)
 */
record RestartNote(String cause, Instant at) {

    static final String FILE = "restart-note.properties";
    static final String HUNG = "stopped responding";
    static final String UNCLEAN = "stopped without shutting down cleanly (a crash, a hang, a power cut or a kill); "
            + "its last sign of life was";

    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm", Locale.ROOT);
    private static final DateTimeFormatter DAY = DateTimeFormatter.ofPattern("d MMM", Locale.ENGLISH);

    static RestartNote exited(int exitCode) {
        return new RestartNote("ended unexpectedly (exit code " + exitCode + ")", Instant.now());
    }

    /**
     * @return e.g. {@code TinySEP was restarted at 10:02 after it stopped responding at 09:58} (with the day when the
     *         two are on different days)
     */
    String sentence(Instant restarted, ZoneId zone) {
        LocalDate day = restarted.atZone(zone).toLocalDate();
        return "TinySEP was restarted at " + time(restarted, zone, null) + " after it " + cause + " at "
                + time(at, zone, day) + " (" + zone.getId() + ")";
    }

    private static String time(Instant t, ZoneId zone, LocalDate sameDayAs) {
        String hhmm = HH_MM.format(t.atZone(zone));
        return sameDayAs == null || sameDayAs.equals(t.atZone(zone).toLocalDate()) ? hhmm
                : hhmm + " on " + DAY.format(t.atZone(zone));
    }

    void write(Path var) throws IOException {
        StateFile.write(var.resolve(FILE), Map.of("cause", cause, "at", at.toString()), true);
    }

    /** Adds the sentence for a restart at {@code restarted} to the note, for the runtime's restart reporter. */
    void complete(Path var, Instant restarted, ZoneId zone) throws IOException {
        StateFile.write(var.resolve(FILE), Map.of("cause", cause, "at", at.toString(), "restarted",
                restarted.toString(), "message", sentence(restarted, zone)), true);
    }

    static Optional<RestartNote> read(Path var) {
        return StateFile.read(var.resolve(FILE)).filter(m -> m.containsKey("cause") && m.containsKey("at"))
                .flatMap(m -> {
                    try {
                        return Optional.of(new RestartNote(m.get("cause"), Instant.parse(m.get("at"))));
                    } catch (RuntimeException e) {
                        return Optional.empty();
                    }
                });
    }
}
