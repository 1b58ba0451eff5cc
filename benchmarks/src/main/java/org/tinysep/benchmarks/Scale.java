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

    record Row(int nodes, double createMs, long rssKb, long heapKb, double devicesMs, double bannerMs,
            double restoredMs, long restartRssKb) {
    }

    void run(Bench b, double idleRssKb) throws Exception {
        int[] counts = b.smoke() ? new int[] {20} : new int[] {100, 1_000, 10_000};
        List<Row> rows = new ArrayList<>();
        for (int n : counts) {
            Bench.Installed inst = b.install("scale-" + n);
            double create;
            long rss;
            long heap;
            double devicesMs;
            try (Platform p = inst.start(b.chosen()); Nodes nodes = new Nodes(n, inst.amicaPort())) {
                long t0 = System.nanoTime();
                nodes.announce(1_000);
                Bench.awaitDevices(p, "AmicaMovement", n, Duration.ofMinutes(30));
                create = (System.nanoTime() - t0) / 1e6;
                long d0 = System.nanoTime();
                int lines = p.command("tinysep:devices", Duration.ofMinutes(5)).size();
                devicesMs = (System.nanoTime() - d0) / 1e6;
                rss = p.rssKb();
                heap = p.liveHeapKb();
                if (lines < 2 * n) {
                    throw new IllegalStateException("tinysep:devices listed " + lines + " lines for " + n + " nodes");
                }
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
            rows.add(new Row(n, create, rss, heap, devicesMs, banner, restored, restartRss));
        }
        Report r = b.report();
        r.heading("Scale: devices in one framework");
        r.text("N movement nodes announce themselves (keep-alives at 1,000/s), making 2N devices; then an orderly "
                + "stop and a restart from the backup. Floor: the idle platform's RSS in this run ("
                + (Double.isNaN(idleRssKb) ? "not measured" : Report.mb((long) idleRssKb)) + ").");
        List<List<String>> table = new ArrayList<>();
        for (Row x : rows) {
            table.add(List.of(Integer.toString(x.nodes()), Integer.toString(2 * x.nodes()),
                    Report.f("%.1f s (%.0f nodes/s)", x.createMs() / 1000, x.nodes() / (x.createMs() / 1000)),
                    Report.mb(x.rssKb()), Report.ratio(x.rssKb(), idleRssKb), Report.mb(x.heapKb()),
                    Report.f("%.0f ms", x.devicesMs()), Report.f("%.0f ms", x.bannerMs()),
                    Report.f("%.1f s", x.restoredMs() / 1000), Report.mb(x.restartRssKb())));
        }
        r.table(List.of("nodes", "devices", "creation", "RSS", "× idle", "live heap after GC", "`tinysep:devices`",
                "restart: to banner", "restart: to all devices restored", "RSS after restart"), table);
        List<String> labels = rows.stream().map(x -> Integer.toString(2 * x.nodes())).toList();
        Plot.bars(b.images().resolve("bench-scale.png"), "Memory by number of devices (MB)", "MB", labels,
                List.of(new Plot.Series("RSS", rows.stream().map(x -> x.rssKb() / 1024.0).toList()),
                        new Plot.Series("live heap after GC", rows.stream().map(x -> x.heapKb() / 1024.0).toList())));
        r.text("![scale](../docs/images/bench-scale.png)");
    }
}
