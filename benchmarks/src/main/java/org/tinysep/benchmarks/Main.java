package org.tinysep.benchmarks;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import org.tinysep.tools.cli.Cli;

/**
 * Runs every benchmark against the real distribution and writes RESULTS.md and the plots.
 * <pre>
 * Main [--smoke] [--repeat 3] [--only footprint,scale] [--append] --dist runtime/org.tinysep.launcher/target/tinysep --out benchmarks/RESULTS.md --images docs/images
 * </pre>
 * ({@link BenchFlags}: an unknown flag is refused with exit code 2.)
 * The thesis, throughput and latency steps run {@code --repeat} times (default 3, smoke 1): the last run's tables
 * are shown, every run's headline figures with their spread, and the issue-29 goals ({@link Goals}) are judged on
 * the medians.
 * Exit code 0 when every benchmark ran and reported, 1 when one failed (its section says why).
 */
public final class Main {

    private Main() {
    }

    /** Exit code 2 for a refused command line (one line naming it, then the usage), 1 when a benchmark failed. */
    public static void main(String[] args) {
        BenchFlags flags = new BenchFlags();
        System.exit(Cli.main(flags, args, System.out, System.err, () -> run(flags)));
    }

    /** @throws IllegalArgumentException naming a refused option or argument */
    static int run(String[] args) throws Exception {
        return run(Cli.parse(new BenchFlags(), args));
    }

    static int run(BenchFlags flags) throws Exception {
        boolean smoke = flags.smoke;
        only = List.copyOf(flags.only);
        Path dist = flags.dist;
        Path out = flags.out;
        Path images = flags.images;
        Path work = Files.createTempDirectory("tinysep-bench-");
        Report report = new Report();
        Bench b = new Bench(dist, work, smoke, Bench.chosenOptions(dist), report, images);
        String loadBefore = Machine.load();
        long t0 = System.nanoTime();
        int repeat = flags.repeat(); // runs of the repeated steps
        Footprint footprint = new Footprint();
        step("footprint", report, () -> {
            footprint.run(b);
            report.figure("start.bannerMs", footprint.chosenStartMs);
            report.figure("rss.defaultKb", footprint.chosenIdleRssKb);
            report.figure("start.felixMs", footprint.chosenFelixStartMs);
            report.figure("rss.felixKb", footprint.chosenFelixRssKb);
            report.figure("rss.headlessKb", footprint.headlessIdleRssKb);
        });
        step("thesis scenarios", report, () -> Repeat.run(b, repeat, "Thesis scenarios", rb -> {
            Thesis t = new Thesis();
            t.run(rb);
            return new double[] {t.scenario5Cpu, t.idleCpu, t.felixIdleCpu};
        }, new String[] {"thesis.s5cpu", "thesis.idleCpu", "thesis.felixIdleCpu"}, new String[] {
            "scenario 5, % of one core", "idle, % of one core", "bare Felix idle, % of one core"}));
        step("throughput", report, () -> Repeat.run(b, repeat, "Throughput", rb -> {
            Throughput t = new Throughput();
            t.run(rb);
            return new double[] {t.platformMax, t.bareMax};
        }, new String[] {"throughput.platform", "throughput.bare"}, new String[] {"TinySEP loss-free frames/s",
            "bare receiver loss-free frames/s"}));
        step("latency", report, () -> Repeat.run(b, repeat, "Latency", rb -> {
            Latency l = new Latency();
            l.run(rb);
            return new double[] {l.p50, l.p99, l.echoP50, l.echoP99, l.pacedP50, l.pacedP99};
        }, new String[] {"latency.p50", "latency.p99", "latency.echoP50", "latency.echoP99", "latency.pacedP50",
            "latency.pacedP99"},
                new String[] {"TinySEP p50 µs (1k frames/s)", "TinySEP p99 µs", "bare echo p50 µs, back to back",
                    "bare echo p99 µs, back to back", "bare echo p50 µs, paced like the samples",
                    "bare echo p99 µs, paced"}));
        step("scale", report, () -> {
            Scale scale = new Scale();
            scale.run(b, footprint.chosenIdleRssKb);
            scale.figures.forEach(report::figure); // e.g. scale.create.20000.ms, judged by Goals
        });
        step("lockstep", report, () -> new LockStep72h().run(b));
        step("hotupdate", report, () -> new HotUpdate().run(b));
        String loadAfter = Machine.load();
        Goals.lines(report).forEach(l -> System.out.println("benchmarks: goal " + l));
        StringBuilder md = new StringBuilder();
        if (flags.append && Files.isRegularFile(out)) {
            // sections run later (--only …) added below an earlier run's, with their own machine load
            md.append(Files.readString(out)).append("\n---\n\n# Added by a later run (").append(Instant.now())
                    .append(", sections: ").append(String.join(", ", only)).append("; load average before ")
                    .append(loadBefore).append(", after ").append(loadAfter).append(")\n");
            md.append(Goals.markdown(report)).append(report.markdown());
            Files.writeString(out, md.toString());
            return report.problems.isEmpty() ? 0 : 1;
        }
        md.append("# TinySEP benchmarks").append(smoke ? " (smoke run: a few seconds each, figures not meaningful)" : "")
                .append("\n\nWritten by `./benchmarks/run.sh").append(smoke ? " --smoke" : "").append("` on ")
                .append(Instant.now()).append(" in ").append(Report.f("%.0f s", (System.nanoTime() - t0) / 1e9))
                .append(". Every figure is of the real distribution (`tinysep.jar` as its own process, as a user runs "
                        + "it), beside floors measured in the same run. How to read and re-run: "
                        + "[`benchmarks/README.md`](README.md).\n\n");
        md.append("| machine | |\n|---|---|\n")
                .append("| cores | ").append(Machine.cores()).append(" (").append(Machine.cpuModel()).append(") |\n")
                .append("| memory | ").append(Machine.memory()).append(" |\n")
                .append("| JVM | ").append(Machine.jvm()).append(" |\n")
                .append("| load average (1, 5, 15 min) before | ").append(loadBefore).append(" |\n")
                .append("| load average after | ").append(loadAfter).append(" |\n\n");
        if (busy(loadBefore) || busy(loadAfter)) {
            md.append("**The machine was busy during this run** (load average above its ").append(Machine.cores())
                    .append(" cores): other processes competed for the CPUs and the disk, "
                            + "so times and CPU shares are noisy and "
                            + "pessimistic; compare the ratios to the floors measured beside them, and re-run on a "
                            + "quiet machine before quoting a figure (a quiet re-run is due).\n\n");
        }
        String note = System.getenv("BENCH_MACHINE_NOTE"); // what the machine was doing, said by whoever ran this
        if (note != null && !note.isBlank()) {
            md.append("**The machine during this run:** ").append(note.strip()).append("\n\n");
        }
        Report before = null;
        if (!smoke && Files.isRegularFile(out)) {
            // the previous full run stays beside the new one, and its headline figures become the "before" column
            Path kept = out.resolveSibling("RESULTS-before.md");
            String previous = Files.readString(out);
            Files.writeString(kept, previous);
            before = Before.read(previous);
            md.append("The previous run's file is kept as [`").append(kept.getFileName()).append("`](")
                    .append(kept.getFileName()).append(") (its first line says when it ran; its plots were those "
                            + "now replaced in `docs/images`).\n\n");
        }
        md.append(Goals.markdown(report, before));
        md.append(report.markdown());
        if (only.isEmpty()) {
            try (var notes = Main.class.getResourceAsStream("/closing-notes.md")) {
                md.append(new String(notes.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8));
            }
        }
        md.append(Before.block(report));
        Files.createDirectories(out.toAbsolutePath().getParent());
        Files.writeString(out, md.toString());
        System.out.println("benchmarks: wrote " + out + (report.problems.isEmpty() ? "" : "; failed: " + report.problems));
        return report.problems.isEmpty() ? 0 : 1;
    }

    interface Step {
        void run() throws Exception;
    }

    private static List<String> only = List.of();

    private static void step(String name, Report report, Step step) {
        if (!only.isEmpty() && only.stream().noneMatch(name::startsWith)) {
            return;
        }
        System.out.println("benchmarks: " + name + " (load " + Machine.load() + ")");
        try {
            step.run();
        } catch (Exception e) {
            e.printStackTrace();
            report.problem(name, e);
        }
    }

    private static boolean busy(String load) {
        try {
            return Double.parseDouble(load.split(" ")[0]) > Machine.cores();
        } catch (RuntimeException e) {
            return false;
        }
    }
}
