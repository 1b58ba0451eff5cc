package org.tinysep.benchmarks;

import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.Welcome;

/**
 * Thesis Table 5.3: scenario 5 (50 nodes, 48,228 frames per hour) for 72 virtual hours in lock-step with the
 * Time Controller (clock EXTERNAL, every virtual second that second's frames, then a signed TICK answered DONE):
 * wall time, and the live heap after a full GC at the start and at the end (a leak would show as growth).
 */
final class LockStep72h {

    void run(Bench b) throws Exception {
        long hours = b.smoke() ? 1 : 72;
        Bench.Installed inst = b.install("lockstep");
        Files.writeString(inst.home().resolve("etc/org.tinysep.timecontroller.cfg"), "mode=EXTERNAL\n",
                StandardOpenOption.APPEND);
        long heapStart;
        long heapEnd;
        long rssStart;
        long rssEnd;
        double wall;
        long frames = 0;
        try (MeasuredPlatform p = inst.start(b.chosen()); Nodes nodes = new Nodes(50, inst.amicaPort())) {
            nodes.announce(500);
            Bench.awaitDevices(p, "AmicaMovement", 50, Duration.ofMinutes(2));
            byte[] key = SyncClient.readKey(inst.var().resolve("sync.key"));
            try (SyncClient sync = new SyncClient(new InetSocketAddress("127.0.0.1", inst.syncPort()), 5_000, key)) {
                Welcome w = sync.hello(60);
                if (!w.external()) {
                    throw new IllegalStateException("the Time Controller is not EXTERNAL: " + w);
                }
                heapStart = p.liveHeapKb();
                rssStart = p.rssKb();
                Instant t = w.platformTime().plusSeconds(1).with(java.time.temporal.ChronoField.NANO_OF_SECOND, 0);
                long seconds = hours * 3600;
                double perSecond = Thesis.PACKETS_PER_HOUR[4] / 3600.0;
                double owed = 0;
                long t0 = System.nanoTime();
                for (long s = 0; s < seconds; s++, t = t.plusSeconds(1)) {
                    owed += perSecond;
                    int n = (int) owed;
                    owed -= n;
                    if (n > 0) {
                        nodes.motion(n, 1_000_000);
                        frames += n;
                    }
                    sync.tick(t);
                }
                wall = (System.nanoTime() - t0) / 1e9;
                sync.bye();
            }
            heapEnd = p.liveHeapKb();
            rssEnd = p.rssKb();
        }
        Report r = b.report();
        r.heading("Thesis scenario 5 for " + hours + " virtual hours in lock-step (Table 5.3)");
        r.text("50 nodes, " + Thesis.PACKETS_PER_HOUR[4] + " motion frames per virtual hour, each virtual second's "
                + "frames sent before its signed TICK; the clock is EXTERNAL, so every timer (grace periods, "
                + "inactivity, keep-alive ageing, log rotation) runs on virtual time.");
        r.table(List.of("virtual time", "frames", "wall time", "live heap after GC: start", "end", "RSS: start",
                "end"), List.of(List.of(hours + " h", Long.toString(frames), Report.f("%.1f s", wall),
                Report.mb(heapStart), Report.mb(heapEnd), Report.mb(rssStart), Report.mb(rssEnd))));
        r.text(Report.f("Live heap growth over the run: %s (%s).", Report.mb(heapEnd - heapStart),
                heapEnd <= heapStart * 1.2 ? "no growth beyond GC noise" : "**grew**"));
    }
}
