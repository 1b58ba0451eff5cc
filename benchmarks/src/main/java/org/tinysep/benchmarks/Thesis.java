package org.tinysep.benchmarks;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * Thesis Tables 5.1/5.2: scenarios 1–5 with 10, 20, 30, 40, 50 nodes at the thesis's packet rates (Table 5.1,
 * packets in 1 h / 3600): CPU % of one core and RSS of the platform over a window, beside the idle platform.
 */
final class Thesis {

    static final int[] NODES = {10, 20, 30, 40, 50};
    static final int[] PACKETS_PER_HOUR = {2_155, 7_545, 26_581, 36_704, 48_228};
    static final double[] THESIS_CPU = {0.50, 1.25, 1.50, 1.50, 1.50};
    static final int[] THESIS_KB = {21_276, 21_884, 22_608, 23_140, 23_674};

    double scenario5Cpu = Double.NaN;
    /** The idle platform (50 nodes known, no traffic): CPU % of one core. */
    double idleCpu = Double.NaN;
    /** Its floor: a bare Felix framework (system bundle only, the same JVM options) over the same window. */
    double felixIdleCpu = Double.NaN;

    void run(Bench b) throws Exception {
        double window = b.smoke() ? 3 : 60;
        Bench.Installed inst = b.install("thesis");
        List<List<String>> rows = new ArrayList<>();
        List<Double> cpu = new ArrayList<>();
        try (MeasuredPlatform p = inst.start(b.chosen()); Nodes all = new Nodes(50, inst.amicaPort())) {
            all.announce(500);
            Bench.awaitDevices(p, "AmicaMovement", 50, Duration.ofMinutes(2));
            try (Child felix = new Child(b.chosen(), "felix", b.work().resolve("thesis-felix-cache").toString())) {
                Bench.sleep(b.smoke() ? 1 : 10);
                Proc.CpuWindow idle = Proc.CpuWindow.start(p.pid());
                Proc.CpuWindow floor = Proc.CpuWindow.start(felix.pid());
                Bench.sleep(window);
                idleCpu = idle.percentOfOneCore();
                felixIdleCpu = floor.percentOfOneCore();
            }
            rows.add(List.of("idle (50 nodes known, no traffic)", "0", "0", Report.f("%.2f %%", idleCpu),
                    Report.mb(p.rssKb()), "–", "–"));
            rows.add(List.of("floor: bare Felix, idle over the same window", "–", "–",
                    Report.f("%.2f %%", felixIdleCpu), "–", "–", "–"));
            for (int s = 0; s < NODES.length; s++) {
                double rate = PACKETS_PER_HOUR[s] / 3600.0;
                try (Nodes nodes = new Nodes(NODES[s], inst.amicaPort())) {
                    Proc.CpuWindow w = Proc.CpuWindow.start(p.pid());
                    long frames = Math.max(1, Math.round(rate * window));
                    nodes.motion(frames, (int) Math.ceil(rate)); // paced to whole frames/s, spread over the window
                    double left = window - (System.nanoTime() - w.nanos()) / 1e9;
                    if (left > 0) {
                        Bench.sleep(left);
                    }
                    double c = w.percentOfOneCore();
                    cpu.add(c);
                    if (s == NODES.length - 1) { // scenario 5
                        scenario5Cpu = c;
                    }
                    rows.add(List.of(Integer.toString(s + 1), Integer.toString(NODES[s]), Report.f("%.1f", rate),
                            Report.f("%.2f %%", c), Report.mb(p.rssKb()), Report.f("%.2f %%", THESIS_CPU[s]),
                            Report.mb(THESIS_KB[s])));
                }
            }
        }
        Report r = b.report();
        r.heading("Thesis scenarios 1–5 (Tables 5.1, 5.2)");
        r.text("Each scenario: its nodes send motion frames at the thesis's rate for " + window + " s; CPU = the "
                + "platform process's user+system time over that window, as % of one core (this machine: "
                + Machine.cpuModel() + "); the thesis measured its C# prototype on an i5-480M (% of the whole CPU). "
                + "The idle row's floor, measured in the same window: a bare Felix framework (system bundle only) "
                + "with the same JVM options, started beside the platform.");
        r.table(List.of("scenario", "nodes", "frames/s", "CPU % of one core", "RSS", "thesis CPU", "thesis memory"),
                rows);
        r.text("Goals (issue 29): thesis load (scenario 5) at ≤ 0.5 % of one core: "
                + Report.goalAtMost(scenario5Cpu, 0.5, "%") + "; idle ≤ 0.1 %: " + Report.goalAtMost(idleCpu, 0.1, "%")
                + " (bare Felix idle: " + Report.f("%.2f %%", felixIdleCpu) + ", ratio "
                + Report.ratio(idleCpu, felixIdleCpu) + ").");
        Plot.bars(b.images().resolve("bench-thesis.png"), "CPU % of one core, thesis scenarios 1-5", "%",
                List.of("1", "2", "3", "4", "5"), List.of(new Plot.Series("TinySEP (Java)", cpu),
                        new Plot.Series("thesis prototype (C#)", java.util.Arrays.stream(THESIS_CPU).boxed().toList())));
        r.text("![thesis](../docs/images/bench-thesis.png)");
    }
}
