package org.tinysep.simulator.cli;

import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.time.format.DateTimeParseException;
import org.tinysep.tools.cli.OptionTypes;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/** The simulator's command line as picocli fills it (tools/org.tinysep.tools.cli); {@link #options()} checks it. */
@Command(name = "java -jar org.tinysep.simulator-<version>.jar", sortOptions = false,
        description = "Plays a simulated flat and scenario, or a recorded home, against a TinySEP platform over its "
                + "real wire protocols (simulator/README.md).",
        footer = {"", "Replay of a recorded home instead of a flat and scenario: simulator/README-replay.md."})
final class Flags {

    @Option(names = "--flat", paramLabel = "<dir|flat-a>",
            description = "house.xml + nodes.txt folder, or a built-in flat (default flat-a)")
    String flat = "flat-a";
    @Option(names = "--scenario", paramLabel = "<file|demo-day>",
            description = "timeline file, or a built-in scenario (default demo-day)")
    String scenario = "demo-day";
    @Option(names = "--target", paramLabel = "<host>", description = "the platform's host (default 127.0.0.1)")
    String target = "127.0.0.1";
    @Option(names = "--amica-port", paramLabel = "<n>", converter = OptionTypes.Port.class,
            description = "AmICA UDP bus radio port (default 47011)")
    int amicaPort = 47011;
    @Option(names = "--sunspot-port", paramLabel = "<n>", converter = OptionTypes.Port.class,
            description = "Sun SPOT UDP bus radio port (default 47012)")
    int sunSpotPort = 47012;
    @Option(names = "--sync-port", paramLabel = "<n>", converter = OptionTypes.Port.class,
            description = "Time Controller synchroniser port (default 47020)")
    int syncPort = 47020;
    @Option(names = "--lockstep",
            description = "lock-step with the Time Controller (platform: tinysep:time external)")
    boolean lockstep;
    @Option(names = "--sync-key", paramLabel = "<file>",
            description = "lock-step: the platform's synchroniser key (<state folder>/sync.key)")
    String syncKey;
    @Option(names = "--release-clock",
            description = "lock-step: at the end, BYE returns the platform clock to REAL time")
    boolean releaseClock;
    @Option(names = "--no-pendant", description = "leave out the flat's worn person nodes (a day without the "
            + "pendant: only the room sensors; the demo's TINYSEP_DEMO_PENDANT=0)")
    boolean noPendant;
    @Option(names = "--wait-platform", paramLabel = "<seconds>", converter = OptionTypes.Count.class,
            description = "lock-step: keep asking a platform that does not answer yet (default 0)")
    int waitSeconds;
    @Option(names = "--speed", paramLabel = "<factor>", converter = NonNegative.class,
            description = "real-time mode: virtual seconds per wall second (default 1)")
    double speed = 1;
    @Option(names = "--seed", paramLabel = "<n>", converter = OptionTypes.Seed.class,
            description = "random variations (default 1)")
    long seed = 1;
    @Option(names = "--from", paramLabel = "<HH:MM>", converter = ClockTime.class,
            description = "virtual day span: from (default 00:00)")
    int fromSecond;
    @Option(names = "--until", paramLabel = "<HH:MM>", converter = ClockTime.class,
            description = "virtual day span: until (default 24:00)")
    int untilSecond = 86_400;
    @Option(names = "--date", paramLabel = "<yyyy-mm-dd>", converter = Day.class, description = {
        "the simulated day (default: today, lock-step: the platform's day or the next);",
        "replay: the virtual day of the recording's first day (default: the platform's day, or the next one whose "
                + "start is still ahead)"})
    LocalDate date;
    @Option(names = "--progress", paramLabel = "<minutes>", converter = OptionTypes.Count.class,
            description = "progress line every N virtual minutes (default 60)")
    int progressMinutes = 60;
    @Option(names = "--pace-ms", paramLabel = "<n>", converter = OptionTypes.Count.class,
            description = "lock-step pause after a second with changed values (default 5)")
    int paceMillis = 5;
    @Option(names = "--jitter", paramLabel = "<seconds>", converter = OptionTypes.Count.class,
            description = "scenario times move by up to +- this (default 90)")
    int jitter = 90;
    @Option(names = "--wander", paramLabel = "<p>", converter = NonNegative.class,
            description = "chance per idle second of a short walk (default 0.002; pets x4)")
    double wander = 0.002;
    @Option(names = "--replay", paramLabel = "<file>",
            description = "replay a recorded home: Ordonez *_Sensors.txt or events.csv")
    String replay;
    @Option(names = "--mapping", paramLabel = "<file|ordonez-a|ordonez-b>",
            description = "replay: sensor -> node mapping (default: built-in defaults)")
    String mapping;
    @Option(names = "--rate", paramLabel = "full|changes", converter = RateValue.class, description = {
        "replay: full: every node repeats its state at the thesis rates (default); changes: state changes and "
                + "keep-alives only (lock-step skips quiet seconds, ticking at least every 10 s)"})
    Rate rate = Rate.FULL;
    @Option(names = "--end", paramLabel = "<yyyy-mm-ddTHH:MM:SS>", converter = End.class,
            description = "replay: play on (quiet) until this recorded time, if later than the last event + 900 s "
                    + "(the evaluation harness: a collapse deletes the 12 h after it)")
    LocalDateTime end;

    /** @return the options, checked together */
    Options options() {
        if (!(speed > 0)) {
            throw new IllegalArgumentException("--speed must be > 0");
        }
        if (untilSecond <= fromSecond) {
            throw new IllegalArgumentException("--until must be after --from");
        }
        return new Options(flat, scenario, target, amicaPort, sunSpotPort, syncPort, speed, lockstep, seed, fromSecond,
                untilSecond, date, progressMinutes, paceMillis, jitter, wander, replay, mapping, rate == Rate.FULL,
                syncKey, releaseClock, waitSeconds, end, noPendant);
    }

    /** A finite number >= 0. */
    static final class NonNegative implements ITypeConverter<Double> {
        @Override
        public Double convert(String v) {
            try {
                double d = Double.parseDouble(v);
                if (d >= 0 && !Double.isInfinite(d)) {
                    return d;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("needs a number >= 0, not '" + v + "'");
        }
    }

    /** HH:MM (H:MM too) as seconds of the day, 00:00 to 24:00. */
    static final class ClockTime implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String v) {
            try {
                return v.equals("24:00") ? 86_400 : LocalTime.parse(v.length() == 4 ? "0" + v : v).toSecondOfDay();
            } catch (DateTimeParseException e) {
                throw new TypeConversionException("needs HH:MM (00:00 to 24:00), not '" + v + "'");
            }
        }
    }

    /** yyyy-mm-dd. */
    static final class Day implements ITypeConverter<LocalDate> {
        @Override
        public LocalDate convert(String v) {
            try {
                return LocalDate.parse(v);
            } catch (DateTimeParseException e) {
                throw new TypeConversionException("needs yyyy-mm-dd, not '" + v + "'");
            }
        }
    }

    /** yyyy-mm-ddTHH:MM:SS, a recorded local time. */
    static final class End implements ITypeConverter<LocalDateTime> {
        @Override
        public LocalDateTime convert(String v) {
            try {
                return LocalDateTime.parse(v);
            } catch (DateTimeParseException e) {
                throw new TypeConversionException("needs yyyy-mm-ddTHH:MM:SS (recorded local time), not '" + v + "'");
            }
        }
    }

    /** What a replay sends: every node's state at its rate, or the changes only. */
    enum Rate {
        FULL, CHANGES
    }

    /** full or changes. */
    static final class RateValue implements ITypeConverter<Rate> {
        @Override
        public Rate convert(String v) {
            return switch (v) {
            case "full" -> Rate.FULL;
            case "changes" -> Rate.CHANGES;
            default -> throw new TypeConversionException("needs full or changes, not '" + v + "'");
            };
        }
    }
}
