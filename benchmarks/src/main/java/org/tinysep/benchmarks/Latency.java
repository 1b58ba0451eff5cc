package org.tinysep.benchmarks;

import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.Arrays;
import java.util.List;

/** Round-trip times over loopback: the bare UDP echo (the latency floor), idle and under background frames. */
final class Latency {

    /** @return sorted round trips in µs: {@code samples} datagrams to an echo on {@code port}, one at a time */
    static double[] echo(int port, int samples) throws Exception {
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
            }
        }
        Arrays.sort(us);
        return us;
    }

    static double pct(double[] sorted, double p) {
        return sorted[Math.min(sorted.length - 1, (int) Math.floor(p / 100 * sorted.length))];
    }

    static List<String> cells(double[] sorted) {
        return List.of(Report.f("%.0f µs", pct(sorted, 50)), Report.f("%.0f µs", pct(sorted, 90)),
                Report.f("%.0f µs", pct(sorted, 99)), Report.f("%.0f µs", sorted[sorted.length - 1]),
                Integer.toString(sorted.length));
    }

    void run(Bench b) throws Exception {
        int samples = b.smoke() ? 200 : 2_000;
        int port = Platform.freeUdpPort();
        double[] idle;
        double[] loaded;
        try (Child echo = new Child(b.chosen(), "echo", Integer.toString(port))) {
            echo(port, Math.min(500, samples)); // warm-up
            idle = echo(port, samples);
            int sink = Platform.freeUdpPort();
            try (Child receiver = new Child(b.chosen(), "receiver", Integer.toString(sink));
                    Nodes background = new Nodes(10, sink)) {
                Thread bg = new Thread(() -> {
                    try {
                        background.motion(b.smoke() ? 3_000 : 30_000, 1_000);
                    } catch (Exception ignored) {
                        // the measurement below still stands
                    }
                }, "background-1k");
                bg.start();
                loaded = echo(port, samples);
                bg.join();
            }
        }
        Report r = b.report();
        r.heading("Latency floor: bare UDP echo");
        r.text("One datagram at a time to a bare Java echo in its own JVM and back (127.0.0.1), idle and while a "
                + "background sender offers 1,000 frames/s to a bare receiver. The packet → reaction latency of "
                + "TinySEP (motion frame → Follow Me Light's light command back at the light node) is **not yet "
                + "measured** (see the closing notes): these are the floors it is to be set beside.");
        r.table(List.of("", "p50", "p90", "p99", "max", "samples"),
                List.of(concat("bare echo, idle", cells(idle)), concat("bare echo, 1k frames/s background",
                        cells(loaded))));
    }

    private static List<String> concat(String first, List<String> rest) {
        List<String> out = new java.util.ArrayList<>();
        out.add(first);
        out.addAll(rest);
        return out;
    }
}
