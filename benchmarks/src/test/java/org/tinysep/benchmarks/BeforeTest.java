package org.tinysep.benchmarks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The previous run's figures, written at the end of RESULTS.md and read back by the next run as "before". */
class BeforeTest {

    @Test
    void figuresWrittenByOneRunAreReadBackByTheNext() {
        Report r = new Report();
        r.figure("throughput.platform", 40_000);
        r.figure("throughput.platform", 60_000.5);
        r.figure("throughput.bare", 250_000);
        r.figure("throughput.bare", Double.NaN);
        String md = "# TinySEP benchmarks\n\n| a | b |\n" + Before.block(r);

        Report read = Before.read(md);

        assertEquals(List.of("throughput.platform", "throughput.bare"), read.keys());
        assertEquals(List.of(40_000.0, 60_000.5), read.figures("throughput.platform"));
        assertTrue(Double.isNaN(read.figures("throughput.bare").get(1)), read.figures("throughput.bare").toString());
    }

    @Test
    void aFileWithoutTheBlockOrWithABrokenLineGivesWhatCanBeRead() {
        assertTrue(Before.read("# an old RESULTS.md without figures\n").keys().isEmpty());
        Report read = Before.read(Before.START + "\nlatency.p50 400 x\nlatency.p99 900\n\n" + Before.END);
        assertEquals(List.of("latency.p99"), read.keys());
    }

    @Test
    void theGoalsTableShowsTheBeforeColumnWithItsRatio() {
        Report now = new Report();
        now.figure("latency.p50", 300);
        now.figure("latency.pacedP50", 30);
        Report before = new Report();
        before.figure("latency.p50", 400);
        before.figure("latency.pacedP50", 20);

        String md = Goals.markdown(now, before);

        String row = md.lines().filter(l -> l.contains("p50 ≤ 150 µs")).findFirst().orElseThrow();
        assertTrue(row.endsWith("| 400 µs (20.00×) |"), row);
        String headless = md.lines().filter(l -> l.contains("headless")).findFirst().orElseThrow();
        assertTrue(headless.endsWith("| – |"), headless);
        assertFalse(Goals.markdown(now).contains("before: median"), Goals.markdown(now));
    }
}
