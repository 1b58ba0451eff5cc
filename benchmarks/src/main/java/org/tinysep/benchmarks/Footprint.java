package org.tinysep.benchmarks;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Footprint and start, with the JVM's default options and with the chosen ones: bare JVM and bare Felix (the
 * floors), then the distribution idle (full default bundle set, no devices): start to banner ("n/n bundles
 * active"), to the shell's first answer, idle RSS, live heap after a full GC.
 */
final class Footprint {

    /** idle RSS and start of the platform with the chosen options, for the other sections' ratios */
    double chosenIdleRssKb = Double.NaN;
    double chosenStartMs = Double.NaN;
    double appCdsIdleRssKb = Double.NaN;
    double appCdsStartMs = Double.NaN;
    /** the headless gateway profile (--headless: no web console) with the chosen options */
    double headlessIdleRssKb = Double.NaN;
    double headlessStartMs = Double.NaN;
    /** bare Felix with the chosen options (the goals' floors): RSS and start */
    double chosenFelixRssKb = Double.NaN;
    double chosenFelixStartMs = Double.NaN;
    /** ms from the banner to the line "Web console: …" (bound, or held until its first use) */
    double webAfterBannerMs = Double.NaN;
    /** ms to the web console's first answer (a first request starts a console that starts on first use) */
    double webFirstAnswerMs = Double.NaN;
    /** RSS with the web console in use (after its first answer), chosen options */
    double webInUseRssKb = Double.NaN;
    private double floorsFelixStart = Double.NaN;
    private double felixCpuMs = Double.NaN;

    void run(Bench b) throws Exception {
        Report r = b.report();
        r.heading("Footprint and start: JVM defaults vs the chosen options");
        r.text("Chosen options (`etc/jvm.options` of the distribution, used by `./run.sh` and `bin/tinysep`): `"
                + String.join(" ", b.chosen()) + "`. Idle = the full default bundle set, no devices, "
                + (b.smoke() ? 2 : 10) + " s after the shell answered. Floors: a bare JVM that only waits for input, "
                + "and a bare Felix framework (system bundle only), each with the same options.");
        List<List<String>> rows = new ArrayList<>();
        List<Double> rss = new ArrayList<>();
        List<Double> floorsJvm = new ArrayList<>();
        List<Double> floorsFelix = new ArrayList<>();
        List<String> headless = new ArrayList<>(b.chosen());
        headless.add("TINYSEP_HEADLESS=1"); // an environment entry: the launcher's one switch (also --headless)
        for (List<String> opts : List.of(Bench.DEFAULTS, b.chosen(), headless)) {
            boolean isHeadless = opts == headless;
            String label = opts.isEmpty() ? "JVM defaults" : isHeadless ? "chosen, headless gateway" : "chosen";
            long jvmRss;
            double jvmStart;
            try (Child idle = new Child(opts, "idle")) {
                Bench.sleep(1);
                jvmRss = Proc.rssKb(idle.pid());
                jvmStart = idle.msToReady;
            }
            long felixRss;
            double felixStart;
            try (Child felix = new Child(opts, "felix", b.work().resolve("felix-cache-" + rows.size()).toString())) {
                felixCpuMs = Proc.cpuTicks(felix.pid()) * 1000.0 / Proc.HZ; // CPU to started: less load-bound than wall
                Bench.sleep(1);
                felixRss = Proc.rssKb(felix.pid());
                felixStart = felix.msToReady;
            }
            Bench.Installed inst = b.install("footprint-" + (opts.isEmpty() ? "default" : isHeadless ? "headless" : "chosen"));
            double banner;
            double ready;
            long idleRss;
            long heap;
            String bannerText;
            double cpu;
            double web;
            double firstAnswer = Double.NaN;
            long inUseRss = 0;
            try (MeasuredPlatform p = inst.start(opts)) {
                ready = p.msSinceStart();
                banner = p.msToBanner();
                bannerText = p.banner();
                cpu = p.cpuMsToBanner();
                web = p.msBannerToWeb();
                Bench.sleep(b.smoke() ? 2 : 10);
                idleRss = p.rssKb();
                heap = p.liveHeapKb();
                if (!isHeadless) { // then the console in use: its first request, RSS a few seconds later
                    firstAnswer = p.msToFirstWebAnswer();
                    Bench.sleep(b.smoke() ? 1 : 5);
                    inUseRss = p.rssKb();
                }
            }
            if (isHeadless) {
                headlessIdleRssKb = idleRss;
                headlessStartMs = banner;
            } else if (!opts.isEmpty()) {
                chosenIdleRssKb = idleRss;
                chosenStartMs = banner;
                webAfterBannerMs = web;
                webFirstAnswerMs = firstAnswer;
                webInUseRssKb = inUseRss;
                chosenFelixRssKb = felixRss;
                chosenFelixStartMs = felixStart;
            }
            rss.add(idleRss / 1024.0);
            floorsJvm.add(jvmRss / 1024.0);
            floorsFelix.add(felixRss / 1024.0);
            rows.add(List.of(label, Report.mb(idleRss), Report.mb(heap), Report.mb(jvmRss), Report.mb(felixRss),
                    Report.ratio(idleRss, jvmRss), Report.ratio(idleRss, felixRss),
                    Report.f("%.0f ms", banner), Report.f("%.0f ms", ready), Report.f("%.0f ms", jvmStart),
                    Report.f("%.0f ms", felixStart), Report.ratio(banner, felixStart), Report.f("%.0f ms", cpu),
                    Report.ratio(cpu, felixCpuMs), Double.isNaN(web) ? "–" : Report.f("%.0f ms", web),
                    Double.isNaN(firstAnswer) ? "–" : Report.f("%.0f ms", firstAnswer),
                    isHeadless ? "–" : Report.mb(inUseRss)));
            floorsFelixStart = felixStart;
            r.text("Banner (" + label + "): `" + bannerText + "`");
        }
        // AppCDS: an archive of the classes a first start loaded (-XX:ArchiveClassesAtExit), used by the next start
        Bench.Installed cds = b.install("footprint-appcds");
        java.nio.file.Path jsa = cds.home().resolve("tinysep.jsa");
        List<String> dump = new ArrayList<>(b.chosen());
        dump.add("-XX:ArchiveClassesAtExit=" + jsa);
        try (MeasuredPlatform p = cds.start(dump)) {
            Bench.sleep(b.smoke() ? 1 : 5);
        }
        List<String> withCds = new ArrayList<>(b.chosen());
        withCds.add("-XX:SharedArchiveFile=" + jsa);
        try (MeasuredPlatform p = cds.start(withCds)) {
            double ready = p.msSinceStart();
            double banner = p.msToBanner();
            double cpu = p.cpuMsToBanner();
            Bench.sleep(b.smoke() ? 2 : 10);
            long idleRss = p.rssKb();
            long heap = p.liveHeapKb();
            rows.add(List.of("chosen + AppCDS archive (" + Report.mb(java.nio.file.Files.size(jsa) / 1024) + ")",
                    Report.mb(idleRss), Report.mb(heap), "–", "–", "–", "–", Report.f("%.0f ms", banner),
                    Report.f("%.0f ms", ready), "–", "–", Report.ratio(banner, floorsFelixStart),
                    Report.f("%.0f ms", cpu), Report.ratio(cpu, felixCpuMs), "–", "–", "–"));
            appCdsIdleRssKb = idleRss;
            appCdsStartMs = banner;
        }
        r.table(List.of("JVM options", "TinySEP idle RSS", "live heap after GC", "bare JVM RSS", "bare Felix RSS",
                "× bare JVM", "× bare Felix", "start to banner (all bundles active)", "start to shell answer",
                "bare JVM start", "bare Felix start", "start × bare Felix", "CPU to banner", "CPU × bare Felix's",
                "web console line, after the banner", "web console: first request answered",
                "RSS, web console in use"), rows);
        r.text("Goals (issue 29): idle RSS with the web console ≤ 80 MB: "
                + Report.goalAtMost(chosenIdleRssKb / 1024, 80, "MB") + "; headless gateway (`--headless`) ≤ 64 MB: "
                + Report.goalAtMost(headlessIdleRssKb / 1024, 64, "MB") + "; start to the banner ≤ 1 s: "
                + Report.goalAtMost(chosenStartMs / 1000, 1, "s") + ". The web console starts on its first use (its "
                + "port held by the launcher until then): the first request was answered in "
                + Report.f("%.0f ms", webFirstAnswerMs) + ", and the platform then held " + Report.mb((long) webInUseRssKb)
                + " (idle RSS is measured before any request). CPU to the banner is the process's user + "
                + "system time when the banner came: on a loaded machine it moves less than the wall time. AppCDS (an archive "
                + "of the classes a first start loaded, `-XX:ArchiveClassesAtExit`, used by the next start): "
                + Report.f("start %.0f ms vs %.0f ms, idle RSS %s vs %s", appCdsStartMs, chosenStartMs,
                        Report.mb((long) appCdsIdleRssKb), Report.mb((long) chosenIdleRssKb))
                + ". Java 17 archives only classes of the JDK's own class loaders (JDK, launcher, Felix framework), "
                + "not those of OSGi bundles, which are most of TinySEP's; see docs/footprint.md for the decision.");
        r.text("Headless gateway: `./run.sh --headless` (or `TINYSEP_HEADLESS=1`): the web console's group "
                + "`bundles/4-web` (Jetty, the console) is not installed, no HTTP port; everything else as in the default.");
        Path png = b.images().resolve("bench-footprint.png");
        Plot.bars(png, "Resident memory (MB): JVM defaults vs chosen options", "MB",
                List.of("JVM defaults", "chosen", "chosen, headless"),
                List.of(new Plot.Series("TinySEP idle", rss), new Plot.Series("bare Felix", floorsFelix),
                        new Plot.Series("bare JVM", floorsJvm)));
        r.text("![footprint](../docs/images/bench-footprint.png)");
    }
}
