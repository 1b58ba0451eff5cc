package org.tinysep.benchmarks;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The issue-29 goals table: verdicts on the medians, ratios to the floors of the same runs, the spread. */
class GoalsTest {

    private static String line(List<String> lines, String goal) {
        return lines.stream().filter(l -> l.contains(goal)).findFirst().orElseThrow();
    }

    @Test
    void verdictsAreOnTheMedianWithTheRatioToTheFloorOfTheSameRun() {
        Report r = new Report();
        for (double[] run : new double[][] {{90_000, 200_000}, {120_000, 250_000}, {110_000, 220_000}}) {
            r.figure("throughput.platform", run[0]);
            r.figure("throughput.bare", run[1]);
        }
        r.figure("latency.p50", 400);
        r.figure("latency.pacedP50", 20);
        r.figure("latency.echoP50", 10); // back to back: the machine's best case, not the floor of a paced sample
        List<String> lines = Goals.lines(r);
        String abs = line(lines, "≥ 100,000 frames/s");
        assertTrue(abs.startsWith("MET"), abs);
        assertTrue(abs.contains("110,000 frames/s (90,000–120,000, 3 runs)"), abs);
        assertTrue(abs.contains("met in 2 of 3 runs"), abs);
        String rel = line(lines, "≥ 40 % of the bare receiver");
        assertTrue(rel.startsWith("MET"), rel); // per-run ratios 0.45, 0.48, 0.50
        assertTrue(rel.contains("ratio 0.48× (0.45–0.50)"), rel);
        String p50 = line(lines, "p50 ≤ 150 µs");
        assertTrue(p50.startsWith("MISSED"), p50);
        assertTrue(p50.contains("ratio 20.00×"), p50);
        assertTrue(line(lines, "headless").startsWith("not measured"), line(lines, "headless"));
        assertTrue(Goals.markdown(r).contains("| loss-free throughput ≥ 100,000 frames/s |"), Goals.markdown(r));
    }

    @Test
    void idleIsJudgedBesideABareFelixOverTheSameWindow() {
        Report r = new Report();
        r.figure("thesis.idleCpu", 0.2);
        r.figure("thesis.felixIdleCpu", 0.05);
        String idle = line(Goals.lines(r), "idle ≤ 0.1 %");
        assertTrue(idle.startsWith("MISSED"), idle);
        assertTrue(idle.contains("floor 0.05 %; ratio 4.00×"), idle);
    }
}
