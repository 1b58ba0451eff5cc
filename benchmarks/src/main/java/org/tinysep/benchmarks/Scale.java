package org.tinysep.benchmarks;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * Scale: N AmICA movement nodes (distinct addresses over several netgroups) each announce themselves: 2N devices
 * (bus device + movement device). Measured: creation time, RSS, live heap, {@code tinysep:devices} time, then an
 * orderly stop and a restart: start to banner and to all devices restored from the backup.
 */
final class Scale {

    record Row(int nodes, double createMs, long rssKb, long heapKb, double devicesMs, double stopMs, long backupFiles,
            double bannerMs, double restoredMs, long restartRssKb) {
    }

    /**
     * Announces all nodes (keep-alives at 1,000/s) and repeats the announcement while devices are missing: keep-alives
     * the kernel dropped at the radio's full socket (creation is slower than 1,000/s) are sent again. Bounded: 20
     * rounds, 30 min. @return ms from {@code t0} until all N movement devices exist
     */
    private static double announceAll(Platform p, Nodes nodes, int n, long t0) throws Exception {
        long deadline = t0 + Duration.ofMinutes(30).toNanos();
        for (int round = 0; round < 20 && System.nanoTime() < deadline; round++) {
            nodes.announce(1_000);
            int last = -1;
            while (System.nanoTime() < deadline) {
                int now = Bench.devicesPerDriver(p).getOrDefault("AmicaMovement", 0);
                if (now >= n) {
                    return (System.nanoTime() - t0) / 1e6;
                }
                if (now == last) {
                    break; // no longer growing: the rest was dropped, announce again
                }
                last = now;
                Thread.sleep(2_000);
            }
        }
        throw new IllegalStateException("not all " + n + " nodes became devices: "
                + Bench.devicesPerDriver(p).getOrDefault("AmicaMovement", 0));
    }

    void run(Bench b, double idleRssKb) throws Exception {
        // nodes; each makes 2 devices (bus + movement): 100, 1,000 and 10,000 devices
        int[] counts = b.smoke() ? new int[] {20} : new int[] {50, 500, 5_000};
        String only = System.getenv("BENCH_SCALE_NODES"); // e.g. 5000 while working on one size
        if (only != null && !only.isBlank()) {
            counts = java.util.Arrays.stream(only.split(",")).mapToInt(x -> Integer.parseInt(x.strip())).toArray();
        }
        List<Row> rows = new ArrayList<>();
        List<String> failed = new ArrayList<>();
        for (int n : counts) {
            try {
                rows.add(measure(b, n));
            } catch (Exception e) {
                failed.add(n + " nodes: " + e);
            }
        }
        report(b, idleRssKb, rows);
        if (!failed.isEmpty()) {
            throw new IllegalStateException("scale: " + failed);
        }
    }

    private static Row measure(Bench b, int n) throws Exception {
        Bench.Installed inst = b.install("scale-" + n);
        double create;
        long rss;
        long heap;
        double devicesMs;
        Platform first = inst.start(b.chosen());
        try (Platform p = first; Nodes nodes = new Nodes(n, inst.amicaPort())) {
            long t0 = System.nanoTime();
            create = announceAll(p, nodes, n, t0);
            long d0 = System.nanoTime();
            int lines = p.command("tinysep:devices", Duration.ofMinutes(5)).size();
            devicesMs = (System.nanoTime() - d0) / 1e6;
            rss = p.rssKb();
            heap = p.liveHeapKb();
            if (lines < 2 * n) {
                throw new IllegalStateException("tinysep:devices listed " + lines + " lines for " + n + " nodes");
            }
        }
        double stopMs = first.msToStop();
        long backupFiles;
        try (java.util.stream.Stream<java.nio.file.Path> f = java.nio.file.Files.walk(inst.var().resolve("backup"))) {
            backupFiles = f.filter(x -> x.toString().endsWith(".xml")).count();
        }
        double banner;
        double restored;
        long restartRss;
        try (Platform p = inst.start(b.chosen())) {
            banner = p.msToBanner();
            Bench.awaitDevices(p, "AmicaMovement", n, Duration.ofMinutes(30));
            restored = p.msSinceStart();
            restartRss = p.rssKb();
        }
        return new Row(n, create, rss, heap, devicesMs, stopMs, backupFiles, banner, restored, restartRss);
    }

    private static void report(Bench b, double idleRssKb, List<Row> rows) throws Exception {
        Report r = b.report();
        r.heading("Scale: devices in one framework");
        r.text("N movement nodes announce themselves (keep-alives at 1,000/s, sent again while some are missing: creation is slower than 1,000/s and the kernel drops what the radio's socket cannot hold), making 2N devices; then an orderly "
                + "stop and a restart from the backup. Floor: the idle platform's RSS in this run ("
                + (Double.isNaN(idleRssKb) ? "not measured" : Report.mb((long) idleRssKb)) + ").");
        List<List<String>> table = new ArrayList<>();
        for (Row x : rows) {
            table.add(List.of(Integer.toString(x.nodes()), Integer.toString(2 * x.nodes()),
                    Report.f("%.1f s (%.0f nodes/s)", x.createMs() / 1000, x.nodes() / (x.createMs() / 1000)),
                    Report.mb(x.rssKb()), Report.ratio(x.rssKb(), idleRssKb), Report.mb(x.heapKb()),
                    Report.f("%.0f ms", x.devicesMs()), Report.f("%.1f s", x.stopMs() / 1000),
                    Long.toString(x.backupFiles()), Report.f("%.0f ms", x.bannerMs()),
                    Report.f("%.1f s", x.restoredMs() / 1000), Report.mb(x.restartRssKb())));
        }
        r.table(List.of("nodes", "devices", "creation", "RSS", "× idle", "live heap after GC", "`tinysep:devices`",
                "orderly stop", "backup files after the stop", "restart: to banner", "restart: to all devices restored", "RSS after restart"), table);
        List<String> labels = rows.stream().map(x -> Integer.toString(2 * x.nodes())).toList();
        Plot.bars(b.images().resolve("bench-scale.png"), "Memory by number of devices (MB)", "MB", labels,
                List.of(new Plot.Series("RSS", rows.stream().map(x -> x.rssKb() / 1024.0).toList()),
                        new Plot.Series("live heap after GC", rows.stream().map(x -> x.heapKb() / 1024.0).toList())));
        r.text("![scale](../docs/images/bench-scale.png)");
    }
}
