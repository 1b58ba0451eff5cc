package org.tinysep.benchmarks;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

/**
 * Runs a step several times (the throughput figure swung 2× between runs) and reports how stable its
 * headline figures are: every run's value, min, median and max. Only the last run writes its detailed section
 * and plots; the others write to a scratch report.
 */
final class Repeat {

    /** One run of the step against {@code bench}; @return its headline figures, in the order of the keys */
    interface Run {
        double[] run(Bench bench) throws Exception;
    }

    private Repeat() {
    }

    static void run(Bench b, int times, String title, Run step, String[] keys, String[] names) throws Exception {
        int n = Math.max(1, times);
        List<double[]> runs = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            boolean last = i == n - 1;
            Bench rb = last ? b : new Bench(b.dist(), b.work().resolve("repeat-" + title + "-" + i), b.smoke(),
                    b.chosen(), new Report(), Files.createDirectories(b.work().resolve("images-" + title + "-" + i)));
            Files.createDirectories(rb.work());
            System.out.println("benchmarks: " + title + ", run " + (i + 1) + " of " + n + " (load " + Machine.load()
                    + ")");
            double[] v = step.run(rb);
            runs.add(v);
            for (int k = 0; k < keys.length; k++) {
                b.report().figure(keys[k], v[k]);
            }
        }
        List<String> header = new ArrayList<>(List.of("figure"));
        for (int i = 1; i <= n; i++) {
            header.add("run " + i);
        }
        header.addAll(List.of("min", "median", "max", "spread (max ÷ min)"));
        List<List<String>> rows = new ArrayList<>();
        for (int k = 0; k < keys.length; k++) {
            List<Double> values = new ArrayList<>();
            List<String> row = new ArrayList<>(List.of(names[k]));
            for (double[] r : runs) {
                values.add(r[k]);
                row.add(cell(r[k]));
            }
            double min = Report.min(values);
            row.addAll(List.of(cell(min), cell(Report.median(values)), cell(Report.max(values)),
                    min > 0 ? Report.f("%.2f×", Report.max(values) / min) : "–"));
            rows.add(row);
        }
        b.report().text("**" + title + ": " + n + " run" + (n == 1 ? "" : "s") + "** (the tables above are the last "
                + "run's; each run starts its own platform and floors):");
        b.report().table(header, rows);
    }

    private static String cell(double v) {
        return Double.isNaN(v) ? "n/a" : Math.abs(v) >= 100 ? Report.f("%.0f", v) : Report.f("%.2f", v);
    }
}
