package org.tinysep.benchmarks;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.simulator.measure.KernelDrops;
import org.tinysep.tools.process.Ports;

/**
 * Maximum zero-loss throughput: N AmICA movement nodes send motion frames round-robin, the rate stepped up until
 * the first loss. Loss at the platform: the kernel's drops at the radio's socket ({@code /proc/net/udp} and
 * {@code udp6}), the radio's own counters ({@code received} minus {@code rejected}) against the frames sent. The bare receiver (a JVM that only counts) is stepped the same way in the same run.
 */
final class Throughput {

    record Step(int offered, double achieved, long sent, long taken, long kernelDrops) {
        boolean lossless() {
            return taken == sent && kernelDrops <= 0;
        }
    }

    double platformMax = Double.NaN;
    double bareMax = Double.NaN;

    void run(Bench b) throws Exception {
        int nodes = b.smoke() ? 5 : 50;
        double seconds = b.smoke() ? 1 : 4;
        int[] rates = b.smoke() ? new int[] {1_000, 2_000}
                : new int[] {5_000, 10_000, 20_000, 40_000, 60_000, 80_000, 100_000, 120_000, 150_000, 200_000, 250_000};
        List<Step> bare = new ArrayList<>();
        int barePort = Ports.freeUdp();
        try (Child receiver = new Child(b.chosen(), "receiver", Integer.toString(barePort));
                Nodes sender = new Nodes(nodes, barePort, Nodes.SENDERS)) {
            for (int rate : rates) {
                long before = Long.parseLong(receiver.ask());
                long dropsBefore = KernelDrops.at(barePort);
                long sentBefore = sender.sent;
                double wall = sender.motion((long) (rate * seconds), rate);
                long sent = sender.sent - sentBefore;
                long got = settle(() -> Long.parseLong(receiver.ask()) - before, sent);
                Step s = new Step(rate, sent / wall, sent, got, KernelDrops.at(barePort) - dropsBefore);
                bare.add(s);
                if (!s.lossless()) {
                    break;
                }
            }
        }
        List<Step> platform = new ArrayList<>();
        Bench.Installed inst = b.install("throughput");
        try (MeasuredPlatform p = inst.start(b.chosen()); Nodes sender = new Nodes(nodes, inst.amicaPort(), Nodes.SENDERS)) {
            sender.announce(2_000);
            Bench.awaitDevices(p, "AmicaMovement", nodes, Duration.ofMinutes(2));
            for (int rate : rates) {
                Bench.RadioCounters before = Bench.radio(p);
                long dropsBefore = KernelDrops.at(inst.amicaPort());
                long sentBefore = sender.sent;
                double wall = sender.motion((long) (rate * seconds), rate);
                long sent = sender.sent - sentBefore;
                long taken = settle(() -> Bench.radio(p).received() - before.received(), sent);
                long rejected = Bench.radio(p).rejected() - before.rejected();
                Step s = new Step(rate, sent / wall, sent, taken - rejected, KernelDrops.at(inst.amicaPort()) - dropsBefore);
                platform.add(s);
                if (!s.lossless()) {
                    break;
                }
            }
        }
        platformMax = max(platform);
        bareMax = max(bare);
        Report r = b.report();
        r.heading("Maximum zero-loss throughput (" + nodes + " AmICA movement nodes, motion frames)");
        r.text("Each step sends for " + seconds + " s at the offered rate (" + Nodes.SENDERS + " sender threads, each its own socket and "
                + "its share of the nodes, paced per ms; the same sender for TinySEP and the bare receiver; on this "
                + Machine.cores() + "-core machine sender and receiver share the cores); a step is "
                + "loss-free when every frame sent was taken (platform: the radio's own `received` counter minus `rejected`, from `tinysep:drivers`; "
                + "bare receiver: its count) and the kernel dropped none at the socket (`/proc/net/udp` + `udp6`). "
                + "Stepping stops at the first loss. The full path runs: radio → movement devices → Flat Occupancy, "
                + "Follow Me Light, Inactivity Recognition (the default bundle set).");
        List<List<String>> rows = new ArrayList<>();
        for (int i = 0; i < Math.max(bare.size(), platform.size()); i++) {
            Step pl = i < platform.size() ? platform.get(i) : null;
            Step ba = i < bare.size() ? bare.get(i) : null;
            int offered = pl != null ? pl.offered() : ba.offered();
            rows.add(List.of(Integer.toString(offered), cells(pl), cells(ba)));
        }
        r.table(List.of("offered frames/s", "TinySEP: achieved/s, taken/sent, kernel drops",
                "bare receiver: achieved/s, counted/sent, kernel drops"), rows);
        r.text(Report.f("Highest loss-free step (the rate achieved by the sender): TinySEP %.0f frames/s, bare receiver %.0f frames/s (TinySEP at %s of "
                + "the bare receiver). Goals: ≥ 100,000 frames/s: %s; ≥ 40 %% of the bare receiver: %s.",
                platformMax, bareMax, Report.ratio(platformMax, bareMax), Report.goalAtLeast(platformMax, 100_000,
                        "frames/s"), Report.goalAtLeast(platformMax / bareMax * 100, 40, "%")));
        Plot.bars(b.images().resolve("bench-throughput.png"), "Highest loss-free rate (frames/s)", "frames/s",
                List.of("TinySEP", "bare receiver"), List.of(new Plot.Series("loss-free frames/s",
                        List.of(platformMax, bareMax))));
        r.text("![throughput](../docs/images/bench-throughput.png)");
    }

    private static String cells(Step s) {
        return s == null ? "–" : Report.f("%.0f, %d/%d, %d%s", s.achieved(), s.taken(), s.sent(), s.kernelDrops(),
                s.lossless() ? "" : " **loss**");
    }

    private static double max(List<Step> steps) {
        // the rate actually achieved: on a busy machine one sender thread may not reach the offered one
        return steps.stream().filter(Step::lossless).mapToDouble(Step::achieved).max().orElse(0);
    }

    interface Count {
        long get() throws Exception;
    }

    /** Waits until the count reaches {@code expected} or stops growing for 1 s (bounded: 30 s). */
    static long settle(Count count, long expected) throws Exception {
        long last = -1;
        long deadline = System.nanoTime() + 30_000_000_000L;
        long stableSince = System.nanoTime();
        while (System.nanoTime() < deadline) {
            long now = count.get();
            if (now >= expected) {
                return now;
            }
            if (now != last) {
                last = now;
                stableSince = System.nanoTime();
            } else if (System.nanoTime() - stableSince > 1_000_000_000L) {
                return now;
            }
            Thread.sleep(100);
        }
        return count.get();
    }
}
