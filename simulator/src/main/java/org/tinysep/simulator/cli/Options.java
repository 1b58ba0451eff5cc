package org.tinysep.simulator.cli;

import java.time.LocalDate;
import java.time.LocalTime;
import java.time.format.DateTimeParseException;
import java.util.Map;
import java.util.TreeMap;

/** The command line, parsed: {@code --name value} pairs and the {@code --lockstep} flag. */
record Options(String flat, String scenario, String target, int amicaPort, int sunSpotPort, int syncPort,
        double speed, boolean lockstep, long seed, int fromSecond, int untilSecond, LocalDate date,
        int progressMinutes, int paceMillis, int jitter, double wander, String replay, String mapping,
        boolean fullRate, String syncKey, boolean releaseClock, int waitSeconds, java.time.LocalDateTime end,
        boolean noPendant) {

    static final String USAGE = """
            usage: java -jar org.tinysep.simulator-<version>.jar [options]
              --flat <dir|flat-a>          house.xml + nodes.txt folder, or a built-in flat (default flat-a)
              --scenario <file|demo-day>   timeline file, or a built-in scenario (default demo-day)
              --target <host>              the platform's host (default 127.0.0.1)
              --amica-port <n>             AmICA UDP bus radio port (default 47011)
              --sunspot-port <n>           Sun SPOT UDP bus radio port (default 47012)
              --sync-port <n>              Time Controller synchroniser port (default 47020)
              --lockstep                   lock-step with the Time Controller (platform: tinysep:time external)
              --sync-key <file>            lock-step: the platform's synchroniser key (<state folder>/sync.key)
              --release-clock              lock-step: at the end, BYE returns the platform clock to REAL time
              --no-pendant                 leave out the flat's worn person nodes (a day without the pendant:
                                           only the room sensors; the demo's TINYSEP_DEMO_PENDANT=0)
              --wait-platform <seconds>    lock-step: keep asking a platform that does not answer yet (default 0)
              --speed <factor>             real-time mode: virtual seconds per wall second (default 1)
              --seed <n>                   random variations (default 1)
              --from <HH:MM> --until <HH:MM>  virtual day span (default 00:00 to 24:00)
              --date <yyyy-mm-dd>          the simulated day (default: today, lock-step: the platform's day or the next)
              --progress <minutes>         progress line every N virtual minutes (default 60)
              --pace-ms <n>                lock-step pause after a second with changed values (default 5)
              --jitter <seconds>           scenario times move by up to +- this (default 90)
              --wander <p>                 chance per idle second of a short walk (default 0.002; pets x4)
            replay of a recorded home instead of a flat and scenario (simulator/README-replay.md):
              --replay <file>              Ordonez *_Sensors.txt or events.csv
              --mapping <file|ordonez-a|ordonez-b>  sensor -> node mapping (default: built-in defaults)
              --rate full|changes          full: every node repeats its state at the thesis rates (default);
                                           changes: state changes and keep-alives only (lock-step skips quiet
                                           seconds, ticking at least every 10 s)
              --date <yyyy-mm-dd>          the virtual day of the recording's first day (default: the platform's
                                           day, or the next one whose start is still ahead)
              --end <yyyy-mm-ddTHH:MM:SS>  play on (quiet) until this recorded time, if later than the last event
                                           + 900 s (the evaluation harness: a collapse deletes the 12 h after it)
            """;

    static Options parse(String[] args) {
        Map<String, String> m = new TreeMap<>();
        boolean lockstep = false;
        boolean release = false;
        boolean noPendant = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--lockstep")) {
                lockstep = true;
            } else if (a.equals("--release-clock")) {
                release = true;
            } else if (a.equals("--no-pendant")) {
                noPendant = true;
            } else if (a.startsWith("--") && i + 1 < args.length) {
                m.put(a.substring(2), args[++i]);
            } else {
                throw new IllegalArgumentException("unexpected argument '" + a + "'");
            }
        }
        Options o = new Options(take(m, "flat", "flat-a"), take(m, "scenario", "demo-day"), take(m, "target", "127.0.0.1"),
                port(m, "amica-port", 47011), port(m, "sunspot-port", 47012), port(m, "sync-port", 47020),
                number(m, "speed", "1"), lockstep, (long) number(m, "seed", "1"), second(m, "from", "00:00"),
                second(m, "until", "24:00"), m.containsKey("date") ? date(take(m, "date", null)) : null,
                (int) number(m, "progress", "60"), (int) number(m, "pace-ms", "5"), (int) number(m, "jitter", "90"),
                number(m, "wander", "0.002"), take(m, "replay", null), take(m, "mapping", null),
                rate(take(m, "rate", "full")), take(m, "sync-key", null), release,
                (int) number(m, "wait-platform", "0"), m.containsKey("end") ? end(take(m, "end", null)) : null,
                noPendant);
        if (!m.isEmpty()) {
            throw new IllegalArgumentException("unknown option(s) " + m.keySet());
        }
        if (!(o.speed > 0)) {
            throw new IllegalArgumentException("--speed must be > 0");
        }
        if (o.untilSecond <= o.fromSecond) {
            throw new IllegalArgumentException("--until must be after --from");
        }
        return o;
    }

    /** @return the synchroniser key of {@code --sync-key}, or null without the option */
    byte[] syncKeyBytes() throws java.io.IOException {
        if (syncKey == null) {
            return null;
        }
        try {
            return org.tinysep.simulator.time.SyncClient.readKey(java.nio.file.Path.of(syncKey));
        } catch (java.io.IOException e) {
            throw new java.io.IOException("--sync-key " + syncKey + ": cannot read the platform's synchroniser key ("
                    + e + ")", e);
        }
    }

    private static boolean rate(String v) {
        return switch (v) {
        case "full" -> true;
        case "changes" -> false;
        default -> throw new IllegalArgumentException("--rate needs full or changes, not '" + v + "'");
        };
    }

    private static String take(Map<String, String> m, String key, String fallback) {
        String v = m.remove(key);
        return v == null ? fallback : v;
    }

    private static double number(Map<String, String> m, String key, String fallback) {
        String v = take(m, key, fallback);
        try {
            double d = Double.parseDouble(v);
            if (d < 0 || Double.isNaN(d) || Double.isInfinite(d)) {
                throw new NumberFormatException();
            }
            return d;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--" + key + " needs a number >= 0, not '" + v + "'");
        }
    }

    private static int port(Map<String, String> m, String key, int fallback) {
        double p = number(m, key, Integer.toString(fallback));
        if (p < 1 || p > 65535 || p != Math.rint(p)) {
            throw new IllegalArgumentException("--" + key + " needs a port 1..65535");
        }
        return (int) p;
    }

    private static int second(Map<String, String> m, String key, String fallback) {
        String v = take(m, key, fallback);
        try {
            return v.equals("24:00") ? 86400 : LocalTime.parse(v.length() == 4 ? "0" + v : v).toSecondOfDay();
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("--" + key + " needs HH:MM (00:00 to 24:00), not '" + v + "'");
        }
    }

    private static java.time.LocalDateTime end(String v) {
        try {
            return java.time.LocalDateTime.parse(v);
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("--end needs yyyy-mm-ddTHH:MM:SS (recorded local time), not '" + v + "'");
        }
    }

    private static LocalDate date(String v) {
        try {
            return LocalDate.parse(v);
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("--date needs yyyy-mm-dd, not '" + v + "'");
        }
    }
}
