package org.tinysep.benchmarks;

import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.Arrays;
import java.util.List;
import org.tinysep.tools.process.Ports;

/**
 * Packet → reaction latency of TinySEP ({@link Reaction}: motion frame → light command via Follow Me Light) beside
 * the bare UDP echo's round trip (the floor), each idle and under 1,000 background frames/s. The reaction's samples
 * are one every {@code interval} ms (the rooms take turns), so the floor the goals are judged against is the echo
 * <em>paced the same way</em>: on this machine a round trip after a 175 ms pause cost 297 µs (p50) where back-to-back
 * round trips cost 18 µs (the threads sleep and their CPU idles between samples); the back-to-back echo stays in the
 * table as the machine's best case.
 */
final class Latency {

    /** Under 1,000 background frames/s: TinySEP's and the bare echo's p50 and p99 (µs); NaN until measured. */
    double p50 = Double.NaN;
    double p99 = Double.NaN;
    double echoP50 = Double.NaN;
    double echoP99 = Double.NaN;
    /** Under 1,000 background frames/s: the bare echo paced like the reaction's samples, p50 and p99 (µs). */
    double pacedP50 = Double.NaN;
    double pacedP99 = Double.NaN;

    /** @return sorted round trips in µs: {@code samples} datagrams to an echo on {@code port}, one at a time */
    static double[] echo(int port, int samples) throws Exception {
        return echo(port, samples, 0);
    }

    /**
     * @param pauseMillis how long to wait after each round trip (0: back to back), like the reaction's samples
     * @return sorted round trips in µs: {@code samples} datagrams to an echo on {@code port}, one at a time
     */
    static double[] echo(int port, int samples, long pauseMillis) throws Exception {
        double[] us = new double[samples];
        try (DatagramChannel ch = DatagramChannel.open()) {
            ch.bind(new InetSocketAddress("127.0.0.1", 0));
            ch.connect(new InetSocketAddress("127.0.0.1", port));
            ByteBuffer out = ByteBuffer.wrap(new byte[16]);
            ByteBuffer in = ByteBuffer.allocate(64);
            for (int i = 0; i < samples; i++) {
                out.rewind();
                in.clear();
                long t0 = System.nanoTime();
                ch.write(out);
                ch.read(in);
                us[i] = (System.nanoTime() - t0) / 1e3;
                if (pauseMillis > 0) {
                    Thread.sleep(pauseMillis);
                }
            }
        }
        Arrays.sort(us);
        return us;
    }

    static double pct(double[] sorted, double p) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        return sorted[Math.min(sorted.length - 1, (int) Math.floor(p / 100 * sorted.length))];
    }

    static List<String> cells(double[] sorted) {
        if (sorted.length == 0) {
            return List.of("–", "–", "–", "–", "0");
        }
        return List.of(Report.f("%.0f µs", pct(sorted, 50)), Report.f("%.0f µs", pct(sorted, 90)),
                Report.f("%.0f µs", pct(sorted, 99)), Report.f("%.0f µs", sorted[sorted.length - 1]),
                Integer.toString(sorted.length));
    }

    void run(Bench b) throws Exception {
        int samples = b.smoke() ? 200 : 2_000;
        int rooms = b.smoke() ? 16 : 40;
        int reactions = b.smoke() ? 16 : 1_000;
        long interval = b.smoke() ? 50 : Math.max(20, (Reaction.GRACE_SECONDS + 2) * 1000L / rooms);
        int pacedSamples = b.smoke() ? 16 : 300;
        int port = Ports.freeUdp();
        double[] idle;
        double[] loaded;
        double[] pacedIdle;
        double[] pacedLoaded;
        try (Child echo = new Child(b.chosen(), "echo", Integer.toString(port))) {
            echo(port, Math.min(500, samples)); // warm-up
            idle = echo(port, samples);
            pacedIdle = echo(port, pacedSamples, interval);
            int sink = Ports.freeUdp();
            try (Child receiver = new Child(b.chosen(), "receiver", Integer.toString(sink));
                    Nodes background = new Nodes(10, sink)) {
                long frames = (long) ((pacedSamples * interval / 1000.0 + samples / 10_000.0 + 3) * 1000);
                Thread bg = new Thread(() -> {
                    try {
                        background.motion(b.smoke() ? 3_000 : frames, 1_000);
                    } catch (Exception ignored) {
                        // the measurement below still stands
                    }
                }, "background-1k");
                bg.start();
                Bench.sleep(1);
                loaded = echo(port, samples);
                pacedLoaded = echo(port, pacedSamples, interval);
                bg.join();
            }
        }
        long[] missedIdle = {0};
        long[] missedLoaded = {0};
        double[] platformIdle;
        double[] platformLoaded;
        Bench.Installed inst = b.install("reaction");
        Reaction.prepare(inst, rooms);
        try (MeasuredPlatform p = inst.start(b.chosen()); Reaction reaction = new Reaction(rooms, inst.amicaPort());
                Nodes background = new Nodes(10, inst.amicaPort())) {
            reaction.announce(p);
            background.announce(100);
            reaction.measure(rooms, interval, new long[1]); // warm-up: every room once (the flat becomes OCCUPIED)
            Bench.sleep(Reaction.GRACE_SECONDS + 3);
            platformIdle = reaction.measure(reactions, interval, missedIdle);
            Bench.sleep(Reaction.GRACE_SECONDS + 3);
            long frames = (long) ((reactions * interval / 1000.0 + 3) * 1000);
            Thread bg = new Thread(() -> {
                try {
                    background.motion(frames, 1_000);
                } catch (Exception ignored) {
                    // the samples below still stand
                }
            }, "background-1k");
            bg.start();
            Bench.sleep(1);
            platformLoaded = reaction.measure(reactions, interval, missedLoaded);
            bg.join();
        }
        p50 = pct(platformLoaded, 50);
        p99 = pct(platformLoaded, 99);
        echoP50 = pct(loaded, 50);
        echoP99 = pct(loaded, 99);
        pacedP50 = pct(pacedLoaded, 50);
        pacedP99 = pct(pacedLoaded, 99);
        Report r = b.report();
        r.heading("Packet → reaction latency (Follow Me Light) beside the bare UDP echo");
        r.text("TinySEP: " + rooms + " rooms, each with a movement node and a simple light node placed in it (House "
                + "Information placements); a sample is a motion frame sent by a room's sensor → the light command "
                + "(100 %) received back at that room's light node, through radio → movement device → Flat Occupancy "
                + "/ Follow Me Light → light device → radio. The light nodes confirm every command with a status "
                + "report; Follow Me Light's grace is " + Reaction.GRACE_SECONDS + " s, so the rooms take turns "
                + "(one sample every " + interval + " ms). Background: 10 further movement nodes (in no room) at "
                + "1,000 frames/s. Samples not answered within 2 s are counted as missed. The floor: a bare Java "
                + "UDP echo in its own JVM, one datagram at a time, idle and while 1,000 frames/s go to a bare "
                + "receiver; *paced* = one round trip every " + interval + " ms like the samples (the floor of the "
                + "goals: after a pause the sleeping threads and idle CPUs cost what back-to-back round trips do "
                + "not), *back to back* = the machine's best case.");
        r.table(List.of("", "p50", "p90", "p99", "max", "samples", "missed"), List.of(
                concat("TinySEP, idle", cells(platformIdle), missedIdle[0]),
                concat("TinySEP, 1k frames/s background", cells(platformLoaded), missedLoaded[0]),
                concat("bare echo, paced, idle", cells(pacedIdle), 0),
                concat("bare echo, paced, 1k frames/s background", cells(pacedLoaded), 0),
                concat("bare echo, back to back, idle", cells(idle), 0),
                concat("bare echo, back to back, 1k frames/s background", cells(loaded), 0)));
        r.text(Report.f("Ratios to the paced floor (p50, p99): idle %s, %s; under 1k frames/s %s, %s (to the "
                + "back-to-back echo under 1k frames/s: %s, %s). Goals at 1k frames/s: p50 ≤ 150 µs: %s; p99 ≤ 1 ms: "
                + "%s.",
                Report.ratio(pct(platformIdle, 50), pct(pacedIdle, 50)),
                Report.ratio(pct(platformIdle, 99), pct(pacedIdle, 99)),
                Report.ratio(pct(platformLoaded, 50), pct(pacedLoaded, 50)),
                Report.ratio(pct(platformLoaded, 99), pct(pacedLoaded, 99)),
                Report.ratio(pct(platformLoaded, 50), pct(loaded, 50)),
                Report.ratio(pct(platformLoaded, 99), pct(loaded, 99)),
                Report.goalAtMost(pct(platformLoaded, 50), 150, "µs"), Report.goalAtMost(pct(platformLoaded, 99),
                        1000, "µs")));
        Plot.bars(b.images().resolve("bench-latency.png"), "Packet -> reaction p50 / p99 (µs), under 1k frames/s",
                "µs", List.of("p50", "p99"), List.of(
                        new Plot.Series("TinySEP (Follow Me Light)", List.of(pct(platformLoaded, 50),
                                pct(platformLoaded, 99))),
                        new Plot.Series("bare UDP echo, paced", List.of(pct(pacedLoaded, 50),
                                pct(pacedLoaded, 99))),
                        new Plot.Series("bare UDP echo, back to back", List.of(pct(loaded, 50), pct(loaded, 99)))));
        r.text("![latency](../docs/images/bench-latency.png)");
    }

    private static List<String> concat(String first, List<String> rest, long missed) {
        List<String> out = new java.util.ArrayList<>();
        out.add(first);
        out.addAll(rest);
        out.add(Long.toString(missed));
        return out;
    }
}
