package org.tinysep.benchmarks;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.tinysep.simulator.measure.KernelDrops;

/**
 * Hot update against the distribution: while 50 AmICA movement nodes send motion frames at 10,000/s, the AmICA
 * Movement bundle is updated from its jar through the platform's own shell ({@code felix:update <id>}, a real
 * {@code Bundle.update}). Measured per swap: the time {@code update} took, the time until all 50 movement devices
 * are back ({@code tinysep:drivers}), and the frames lost before the radio (kernel drops at its socket, frames sent
 * minus the radio's {@code received}).
 */
final class HotUpdate {

    static final String MOVEMENT_BSN = "org.tinysep.amica.movement";

    record Swap(double updateMs, double backMs, long sent, long received, long kernelDrops) {
        long lostBeforeRadio() {
            return Math.max(sent - received, kernelDrops);
        }
    }

    void run(Bench b) throws Exception {
        int nodes = b.smoke() ? 5 : 50;
        int rate = b.smoke() ? 1_000 : 10_000;
        int swaps = b.smoke() ? 1 : 3;
        double seconds = b.smoke() ? 3 : 8;
        List<Swap> out = new ArrayList<>();
        Bench.Installed inst = b.install("hotupdate");
        try (MeasuredPlatform p = inst.start(b.chosen()); Nodes sender = new Nodes(nodes, inst.amicaPort(), Nodes.SENDERS)) {
            sender.announce(2_000);
            Bench.awaitDevices(p, "AmicaMovement", nodes, Duration.ofMinutes(2));
            String id = bundleId(p);
            for (int i = 0; i < swaps; i++) {
                Bench.RadioCounters before = Bench.radio(p);
                long dropsBefore = KernelDrops.at(inst.amicaPort());
                long sentBefore = sender.sent;
                CompletableFuture<Double> load = CompletableFuture.supplyAsync(() -> {
                    try {
                        return sender.motion((long) (rate * seconds), rate);
                    } catch (java.io.IOException e) {
                        throw new java.io.UncheckedIOException(e);
                    }
                });
                Bench.sleep(seconds / 4);
                long t0 = System.nanoTime();
                p.command("felix:update " + id, Duration.ofMinutes(2));
                double updateMs = (System.nanoTime() - t0) / 1e6;
                Bench.awaitDevices(p, "AmicaMovement", nodes, Duration.ofMinutes(2));
                double backMs = (System.nanoTime() - t0) / 1e6;
                load.get();
                long sent = sender.sent - sentBefore;
                long received = Throughput.settle(() -> Bench.radio(p).received() - before.received(), sent);
                out.add(new Swap(updateMs, backMs, sent, received, KernelDrops.at(inst.amicaPort()) - dropsBefore));
            }
        }
        Report r = b.report();
        r.heading("Hot update of AmICA Movement under " + Report.f("%,d", rate) + " frames/s (the distribution)");
        r.text(nodes + " movement nodes send motion frames at " + Report.f("%,d", rate) + "/s for " + seconds
                + " s; a quarter in, the platform's shell runs `felix:update <id>` of `" + MOVEMENT_BSN + "` (a real "
                + "`Bundle.update` from its jar). *update* = the command's time; *devices back* = until `tinysep:drivers` "
                + "lists all " + nodes + " movement devices again. Lost before the radio = kernel drops at its socket "
                + "(`/proc/net/udp` + `udp6`) or frames sent minus the radio's `received`. Frames the radio received "
                + "but no consumer got cannot be counted from outside the process: `HotUpdateUnderLoadTest` (Pax Exam) "
                + "asserts 0 for them on every swap.");
        List<List<String>> rows = new ArrayList<>();
        for (int i = 0; i < out.size(); i++) {
            Swap s = out.get(i);
            rows.add(List.of(Integer.toString(i + 1), Report.f("%.0f ms", s.updateMs()), Report.f("%.0f ms", s.backMs()),
                    Long.toString(s.sent()), Long.toString(s.received()), Long.toString(s.kernelDrops()),
                    Long.toString(s.lostBeforeRadio())));
        }
        r.table(List.of("swap", "update", "devices back", "frames sent", "received by the radio", "kernel drops",
                "lost before the radio"), rows);
        Plot.bars(b.images().resolve("bench-hotupdate.png"), "Hot update under load: swap time (ms)", "ms",
                out.stream().map(x -> "swap " + (out.indexOf(x) + 1)).toList(),
                List.of(new Plot.Series("update", out.stream().map(Swap::updateMs).toList()),
                        new Plot.Series("devices back", out.stream().map(Swap::backMs).toList())));
        r.text("![hot update](../docs/images/bench-hotupdate.png)");
    }

    /** @return the bundle id of AmICA Movement, from the shell's {@code lb -s} */
    private static String bundleId(MeasuredPlatform p) {
        for (String line : p.command("felix:lb -s", Duration.ofSeconds(60))) {
            if (line.contains(MOVEMENT_BSN + " ") || line.strip().endsWith(MOVEMENT_BSN)
                    || line.contains(MOVEMENT_BSN + "(")) {
                return line.strip().split("\\s*\\|\\s*|\\s+")[0];
            }
        }
        throw new IllegalStateException("no " + MOVEMENT_BSN + " in lb -s");
    }
}
