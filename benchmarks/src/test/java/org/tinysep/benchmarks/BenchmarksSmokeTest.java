package org.tinysep.benchmarks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * CI's short version of {@code ./benchmarks/run.sh}: every benchmark runs for a few seconds against the assembled
 * distribution and reports. Asserts only that it ran and wrote every section and plot, never a figure (the
 * machine is shared; figures are for RESULTS.md from a full run).
 */
class BenchmarksSmokeTest {

    @Test
    void everyBenchmarkRunsAgainstTheDistributionAndReports() throws Exception {
        Path out = Path.of("target/smoke");
        Path results = out.resolve("RESULTS.md");
        int rc = Main.run(new String[] {"--smoke", "--dist", System.getProperty("tinysep.dist"),
            "--out", results.toString(), "--images", out.resolve("images").toString()});
        String md = Files.readString(results);
        System.out.println(md);
        for (String section : List.of("## Footprint and start", "## Thesis scenarios 1–5",
                "## Maximum zero-loss throughput", "## Packet → reaction latency", "## Scale", "virtual hours in lock-step",
                "## Hot update of AmICA Movement",
                "## Issue 29 goals", "load average after")) {
            assertTrue(md.contains(section), "RESULTS.md has " + section);
        }
        for (String png : List.of("bench-footprint.png", "bench-thesis.png", "bench-throughput.png", "bench-scale.png",
                "bench-latency.png", "bench-hotupdate.png")) {
            assertTrue(Files.size(out.resolve("images").resolve(png)) > 1000, png + " drawn");
        }
        assertEquals(0, rc, "every benchmark ran (failures are named in RESULTS.md)");
    }
}
