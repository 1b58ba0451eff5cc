package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.tinysep.tools.cli.Cli;

/**
 * {@code ./evaluate.sh [A|B|folder] [--collapses N] [--seed S] ...}: evaluates the inactivity alert of the real
 * platform on a recorded home (evaluation/README.md) and prints the table, detectors side by side.
 */
public final class Evaluate {

    private Evaluate() {
    }

    /** Exit code 2 for a refused command line (one line naming it, then the usage), 1 for a failed run. */
    public static void main(String[] args) {
        Path repo = Path.of(System.getProperty("tinysep.repo", "."));
        if (args.length > 0 && args[0].equals("falls")) { // fall detection on SisFall: its own options
            String[] rest = java.util.Arrays.copyOfRange(args, 1, args.length);
            System.exit(Cli.run(new org.tinysep.evaluation.falls.FallsFlags(),
                    () -> org.tinysep.evaluation.falls.FallsCommand.main(rest, repo, System.out), System.err));
        }
        EvalFlags flags = new EvalFlags();
        System.exit(Cli.main(flags, args, System.out, System.err, () -> {
            run(flags.options(repo, "./evaluate.sh " + String.join(" ", args)));
            return Cli.OK;
        }));
    }

    /** What a run produced: the table and the figures behind it, per detector. */
    record Outcome(String markdown, Map<String, Experiment.Result> results) {
    }

    /** @return the table written (and printed) and its figures */
    static Outcome run(EvalOptions o) throws Exception {
        String loadBefore = load();
        String commit = commit(); // at the start: the code that runs
        long wall = System.nanoTime();
        Home home = Home.load(o.home(), o.ordonez(), o.work(), o.words());
        if (o.residents() != null) {
            home = home.withResidents(o.residents());
        }
        if (o.days() > 0) {
            home = Days.first(home, o.days());
        }
        Experiment x = new Experiment(o, home);
        Map<String, Experiment.Result> results = x.run();
        long took = (System.nanoTime() - wall) / 1_000_000_000L;
        List<String> facts = new ArrayList<>();
        facts.add("Run " + Instant.now().truncatedTo(ChronoUnit.SECONDS) + ", commit `" + commit + "`, command `"
                + o.command().trim() + "`, " + Report.hm(Duration.ofSeconds(took)) + " wall time");
        if (x.split().name().equals("half")) {
            facts.add("Recording " + home.events().get(0).time() + " .. " + home.end() + " (" + home.events().size()
                    + " events); history (replayed once, its stopped state folder copied for every other run) until "
                    + home.split() + "; test half " + home.split() + " .. " + home.end() + " ("
                    + String.format(java.util.Locale.ROOT, "%.1f", x.testSpan().toSeconds() / 86400.0) + " days)");
        } else {
            facts.add("Recording " + home.events().get(0).time() + " .. " + home.end() + " (" + home.events().size()
                    + " events); **split " + x.split().name() + "**: " + x.split().folds().size() + " folds by days, "
                    + "day i of the recording tested in fold i mod " + x.split().folds().size() + " and learned from in "
                    + "every other fold (history = the other days, replayed once per fold; the test days replayed "
                    + x.split().folds().get(0).extraDays() + " days later than recorded, after the history)");
        }
        facts.add("Inactivity Recognition's `learnHistoryDays` = " + x.historyDays() + " in every platform: the "
                + "default 28 plus how far the harness places replays beyond their recorded time, so no replay loses "
                + "recorded history to its virtual placement");
        facts.add(o.collapses() + " collapses per detector, seed " + o.seed() + ", each replayed from at least "
                + o.warmupHours() + " h before it to 12 h after it; " + o.parallel() + " platforms at once; "
                + (o.batch() == 1 ? "every collapse in its own platform started from a copy of the snapshot"
                        : o.batch() + " collapses per platform started from a copy of the snapshot, one after another "
                                + "in virtual time; **not for published figures**: LEARNED also learns from live "
                                + "activity, so a batch's later windows learn from its earlier windows' test-half events "
                                + "(README: batches)"));
        facts.add("Detector config: `org.tinysep.inactivity` key `detector` = the column's value in "
                + "`etc/org.tinysep.inactivity.cfg` of each platform (the history was replayed with `detector="
                + o.detectors().get(0) + "`)");
        facts.add("Machine: " + Runtime.getRuntime().availableProcessors() + " CPUs, load average before " + loadBefore
                + ", after " + load() + (PlatformRun.retries() == 0 ? ""
                        : "; " + PlatformRun.retries() + " platform run(s) started again because the port chosen for "
                                + "the time synchroniser was taken before the platform bound it (no answer to HELLO)"));
        facts.add(Report.CITATION);
        String title = home.name() + (x.split().name().equals("half") ? "" : "-" + x.split().name());
        String md = Report.markdown(title, facts, results);
        System.out.println();
        System.out.println(md);
        if (o.readme() != null) {
            Readme.put(o.readme(), title, md);
            System.out.println("written to " + o.readme());
        }
        return new Outcome(md, results);
    }

    private static String load() {
        try {
            String[] p = Files.readString(Path.of("/proc/loadavg")).trim().split(" ");
            return p[0] + " " + p[1] + " " + p[2];
        } catch (IOException | RuntimeException e) {
            return "n/a";
        }
    }

    static String commit() {
        try {
            Process p = new ProcessBuilder("git", "rev-parse", "--short=12", "HEAD").redirectErrorStream(true).start();
            String c = new String(p.getInputStream().readAllBytes()).trim();
            Process d = new ProcessBuilder("git", "status", "--porcelain", "--untracked-files=no").start();
            boolean dirty = !new String(d.getInputStream().readAllBytes()).isBlank();
            return p.waitFor() == 0 ? c + (dirty ? " + uncommitted changes" : "") : "unknown";
        } catch (IOException | InterruptedException e) {
            return "unknown";
        }
    }
}
