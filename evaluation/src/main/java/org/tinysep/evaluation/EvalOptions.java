package org.tinysep.evaluation;

import java.nio.file.Path;
import java.util.List;

/**
 * The command line of {@link Evaluate}.
 *
 * @param home        {@code A}, {@code B} (Ordonez) or a folder with events.csv and labels.csv
 * @param collapses   injected collapses per detector
 * @param seed        seed of the collapse draw
 * @param warmupHours replayed before each collapse (at least; see README)
 * @param parallel    platform processes at once
 * @param batch       collapses replayed one after another by one platform process (each in its own virtual weeks)
 * @param days        use only the first N days of the recording (0 = all): the smoke test's short window
 * @param detectors   values of Inactivity Recognition's {@code detector} key, side by side
 * @param ordonez     folder of the Ordonez files
 * @param dist        the assembled distribution (runtime/org.tinysep.launcher/target/tinysep)
 * @param work        folder for state folders and converted files
 * @param readme      README to write the table into (null: print only)
 * @param command     the command line as typed, for the report
 * @param split       {@code half} (history = first half, the headline) or {@code cvK} (K folds by days, {@link Split})
 * @param words       which labelled activities mean away and asleep
 */
record EvalOptions(String home, int collapses, long seed, int warmupHours, int parallel, int batch, int days,
        List<String> detectors, Path ordonez, Path dist, Path work, Path readme, String command, String split,
        LabelWords words) {

    static final String USAGE = """
            usage: ./evaluate.sh [A|B|<folder with events.csv, labels.csv>] [--collapses N] [--seed S]
                   [--warmup-hours H] [--parallel P] [--batch B] [--days D] [--split half|cvK] [--detectors LEARNED,THESIS]
                   [--away-labels REGEX] [--sleep-labels REGEX] [--no-readme]
              A, B          Ordonez Home A / B (default A), converted from data/ordonez (in the repository;
                            --ordonez DIR reads another copy)
              --collapses   injected collapses per detector (default 200)
              --seed        seed of the collapse draw (default 1)
              --warmup-hours  recorded hours replayed before each collapse (default 6)
              --parallel    platform processes at once (default 2)
              --batch       collapses per platform process, one after another in virtual time (default 1: every
                            collapse from its own copy of the snapshot)
              --days        only the first D days of the recording (default all)
              --split       half (default: learn from the first half, test the second) or cvK: K folds by days,
                            every day tested once with the other days as history (cv<days> = leave-one-day-out)
              --away-labels, --sleep-labels  which labelled activities mean away / asleep (case-insensitive regex,
                            found anywhere in the name; defaults match Leaving, Leave_Home, Out, Away, ... and Sleeping,
                            Sleep, go to bed, Nap, ...: README, "Labels")
              --no-readme   print the table only (default: also into evaluation/README.md)
            """;

    static EvalOptions parse(String[] args, Path repo) {
        String home = "A";
        int collapses = 200;
        long seed = 1;
        int warmup = 6;
        int parallel = 2;
        int batch = 1;
        int days = 0;
        String split = "half";
        List<String> detectors = List.of("LEARNED", "THESIS");
        String away = LabelWords.AWAY;
        String sleep = LabelWords.SLEEP;
        Path readme = repo.resolve("evaluation/README.md");
        Path ordonez = repo.resolve("data/ordonez");
        Path dist = repo.resolve("runtime/org.tinysep.launcher/target/tinysep");
        Path work = repo.resolve("evaluation/target/work");
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
            case "--no-readme" -> readme = null;
            case "--collapses" -> collapses = number(args, ++i, a, 0);
            case "--seed" -> seed = number(args, ++i, a, 0);
            case "--warmup-hours" -> warmup = number(args, ++i, a, 1);
            case "--parallel" -> parallel = number(args, ++i, a, 1);
            case "--batch" -> batch = number(args, ++i, a, 1);
            case "--days" -> days = number(args, ++i, a, 0);
            case "--split" -> split = value(args, ++i, a);
            case "--detectors" -> detectors = List.of(value(args, ++i, a).split(","));
            case "--ordonez" -> ordonez = Path.of(value(args, ++i, a));
            case "--dist" -> dist = Path.of(value(args, ++i, a));
            case "--work" -> work = Path.of(value(args, ++i, a));
            case "--readme" -> readme = Path.of(value(args, ++i, a));
            case "--away-labels" -> away = pattern(args, ++i, a);
            case "--sleep-labels" -> sleep = pattern(args, ++i, a);
            default -> {
                if (a.startsWith("--")) {
                    throw new IllegalArgumentException("unknown option " + a + "\n" + USAGE);
                }
                home = a;
            }
            }
        }
        return new EvalOptions(home, collapses, seed, warmup, parallel, batch, days, detectors, ordonez, dist, work, readme,
                "./evaluate.sh " + String.join(" ", args), split, new LabelWords(away, sleep));
    }

    private static String pattern(String[] args, int i, String option) {
        String v = value(args, i, option);
        try {
            java.util.regex.Pattern.compile(v);
            return v;
        } catch (java.util.regex.PatternSyntaxException e) {
            throw new IllegalArgumentException(option + " needs a regular expression: " + e.getDescription()
                    + " in '" + v + "'");
        }
    }

    private static String value(String[] args, int i, String option) {
        if (i >= args.length) {
            throw new IllegalArgumentException(option + " needs a value\n" + USAGE);
        }
        return args[i];
    }

    private static int number(String[] args, int i, String option, int min) {
        String v = value(args, i, option);
        try {
            int n = Integer.parseInt(v);
            if (n < min) {
                throw new NumberFormatException();
            }
            return n;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " needs a whole number >= " + min + ", not '" + v + "'");
        }
    }
}
