package org.tinysep.simulator.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Locale;
import org.tinysep.simulator.replay.EventsCsv;
import org.tinysep.simulator.replay.OrdonezReader;
import org.tinysep.simulator.replay.ReplayFormatException;
import org.tinysep.simulator.replay.ReplayPlan;
import org.tinysep.simulator.replay.SensorEvent;
import org.tinysep.simulator.replay.SensorMapping;

/**
 * What a replay plays: the plan read from a recording and its mapping, and the whole-day shift that moves the
 * recording onto the platform's virtual time (times of day are kept, so night stays night).
 *
 * @param plan      nodes and actions
 * @param shiftDays days added to recorded local times (read as UTC) to get virtual time
 */
public record Replay(ReplayPlan plan, long shiftDays) {

    /** Seconds of keep-alives before the first recorded event, so the platform knows every node by then. */
    public static final long LEAD_SECONDS = 120;
    /** Seconds played after the last recorded event: a leave check (600 s) started by it still ends. */
    public static final long TAIL_SECONDS = 900;

    /** @return the virtual epoch second of a recorded local time */
    public long virtualSecond(LocalDateTime recorded) {
        return recorded.plusDays(shiftDays).toEpochSecond(ZoneOffset.UTC);
    }

    /** @return the recorded local time of a virtual instant (the inverse of {@link #virtualSecond}) */
    public LocalDateTime recordedTime(Instant virtual) {
        return LocalDateTime.ofInstant(virtual, ZoneOffset.UTC).minusDays(shiftDays);
    }

    /** @return the first virtual second played: {@link #LEAD_SECONDS} before the first event */
    public long fromSecond() {
        return virtualSecond(plan.start()) - LEAD_SECONDS;
    }

    /** @return the virtual second after the last one played */
    public long untilSecond() {
        return virtualSecond(plan.end()) + TAIL_SECONDS;
    }

    /**
     * @param recording Ordonez {@code *_Sensors.txt} or generic {@code events.csv} (chosen by the file's first line)
     * @param mapping   a mapping file, or a shipped one by name ({@code ordonez-a}, {@code ordonez-b}), or null
     *                  for the built-in defaults
     * @return the plan
     */
    public static ReplayPlan plan(Path recording, String mapping) throws IOException, ReplayFormatException {
        ReplayPlan plan = ReplayPlan.of(read(recording), mappingOf(mapping));
        if (plan.actions().isEmpty()) {
            throw new ReplayFormatException(recording.toString(), 0, "no sensor events to replay");
        }
        return plan;
    }

    /** @return the replay of {@code plan} whose first recorded day becomes virtual day {@code firstDay} */
    public static Replay on(ReplayPlan plan, LocalDate firstDay) {
        return new Replay(plan, firstDay.toEpochDay() - plan.start().toLocalDate().toEpochDay());
    }

    /**
     * @return the first virtual day on which the recording, lead time included, starts after {@code notBefore}
     */
    static LocalDate firstDayAfter(ReplayPlan plan, Instant notBefore) {
        LocalDate day = LocalDateTime.ofInstant(notBefore, ZoneOffset.UTC).toLocalDate();
        LocalDateTime start = plan.start().minusSeconds(LEAD_SECONDS);
        while (start.plusDays(day.toEpochDay() - plan.start().toLocalDate().toEpochDay())
                .toEpochSecond(ZoneOffset.UTC) <= notBefore.getEpochSecond()) {
            day = day.plusDays(1);
        }
        return day;
    }

    static List<SensorEvent> read(Path recording) throws IOException, ReplayFormatException {
        if (!Files.isRegularFile(recording)) {
            throw new IOException("no recording file " + recording);
        }
        String first;
        try (var lines = Files.lines(recording)) {
            first = lines.findFirst().orElse("");
        }
        return first.strip().toLowerCase(Locale.ROOT).startsWith(EventsCsv.HEADER)
                ? EventsCsv.read(recording) : OrdonezReader.readSensors(recording);
    }

    static SensorMapping mappingOf(String mapping) throws IOException, ReplayFormatException {
        if (mapping == null || mapping.isBlank()) {
            return SensorMapping.defaults();
        }
        Path file = Path.of(mapping);
        if (Files.isRegularFile(file)) {
            return SensorMapping.read(file);
        }
        if (mapping.matches("[a-z0-9-]+")) {
            return SensorMapping.fromResource(mapping + ".mapping");
        }
        throw new IOException("no mapping file '" + mapping + "' (built in: ordonez-a, ordonez-b)");
    }
}
