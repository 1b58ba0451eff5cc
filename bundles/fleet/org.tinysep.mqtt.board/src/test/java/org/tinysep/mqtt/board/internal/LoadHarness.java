package org.tinysep.mqtt.board.internal;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.mqtt.board.loadtest.SimFlat;
import org.tinysep.mqtt.board.loadtest.SimFlats;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * The load test: one real Mosquitto, the board (its real classes: Central, Intake, Board, the Paho link) in this
 * JVM, and N light simulated flats in a second JVM ({@link SimFlats}), each with its own MQTT connection and Last
 * Will, publishing what a flat's bridge publishes. The board acknowledges every alert it sees (the flat answers
 * ACKNOWLEDGED, then CLEARED). Measures: alert latency raised-at-the-flat → applied on the board (p50/p99), the
 * acknowledgement's round trip, messages lost (published and PUBACKed by the broker but never seen by the board),
 * CPU and peak RSS of broker, board and flats from /proc. Writes the report to {@code report}.
 */
final class LoadHarness {

    record Options(int flats, int seconds, int heartbeatSeconds, int stateMillis, int alertSeconds, int occupancySeconds) { }

    private final Options o;
    private final List<Long> alertMicros = Collections.synchronizedList(new ArrayList<>());
    private final List<Long> ackMicros = Collections.synchronizedList(new ArrayList<>());
    private final Map<String, Long> ackSent = new ConcurrentHashMap<>();
    private final AtomicLong opened = new AtomicLong();
    private final AtomicLong ackFailures = new AtomicLong();
    private final ExecutorService acker = Executors.newSingleThreadExecutor();
    private Central central;

    LoadHarness(Options o) {
        this.o = o;
    }

    String run(Path report) throws Exception {
        try (Mosquitto broker = Mosquitto.builder().configLine("max_queued_messages 0").start()) {
            // the test broker lets anyone in: the board connects only with the override (a PROBLEM, here ignored);
            // it follows the flats it has keys for, and the simulated flats sign as the bridge does
            Path var = Files.createTempDirectory("tinysep-load-var");
            Path keys = Files.createDirectories(var.resolve("secrets/flats"));
            for (int i = 1; i <= o.flats(); i++) { // the ids SimFlats gives
                String id = String.format("flat%03d", i);
                Files.writeString(keys.resolve(id + ".key"), SimFlat.key(id));
            }
            central = new Central(Configs.board(Map.of("brokerUrl", broker.url(), "clientId", "load-board",
                    "allowAnonymous", true)), Clock.systemUTC(), this::applied, var, p -> { });
            try {
                Conditions.await("the board connected", Duration.ofSeconds(60), () -> central.json().contains("\"connected\":true"),
                        central::json);
                long brokerPid = ProcessHandle.current().children().filter(p -> p.info().command().orElse("").contains("mosquitto"))
                        .findFirst().orElseThrow().pid();
                Process sim = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m",
                        "-cp", System.getProperty("java.class.path"), SimFlats.class.getName(), broker.url(), "tinysep",
                        "" + o.flats(), "" + o.seconds(), "" + o.heartbeatSeconds(), "" + o.stateMillis(), "" + o.alertSeconds(),
                        "" + o.occupancySeconds()).redirectError(ProcessBuilder.Redirect.INHERIT).start();
                BufferedReader out = new BufferedReader(new InputStreamReader(sim.getInputStream(), StandardCharsets.UTF_8));
                String line = out.readLine();
                if (line == null || !line.startsWith("READY")) {
                    throw new IllegalStateException("the simulated flats did not start: " + line);
                }
                long self = ProcessHandle.current().pid();
                ProcStat b0 = ProcStat.of(brokerPid), s0 = ProcStat.of(self), f0 = ProcStat.of(sim.pid());
                long start = System.nanoTime();
                long[] peak = new long[3];
                String stats = null;
                while (stats == null) { // sample RSS until the flats report
                    peak(peak, brokerPid, self, sim.pid());
                    if (out.ready() || !sim.isAlive()) {
                        stats = out.readLine();
                        if (stats == null) {
                            throw new IllegalStateException("the simulated flats ended without their figures");
                        }
                        if (!stats.startsWith("SIMSTATS")) {
                            stats = null;
                        }
                    } else {
                        Thread.sleep(500);
                    }
                }
                double wall = (System.nanoTime() - start) / 1e9;
                ProcStat b1 = ProcStat.of(brokerPid), s1 = ProcStat.of(self), f1 = ProcStat.of(sim.pid());
                sim.getOutputStream().close();
                sim.waitFor(60, TimeUnit.SECONDS);
                Map<String, Long> sims = parse(stats);
                Conditions.await("the board to read every message the flats published", Duration.ofSeconds(120),
                        () -> central.board().totals().messages() >= sims.get("boardTopics"), () -> central.board().totals().toString());
                String text = report(sims, wall, b0, b1, s0, s1, f0, f1, peak);
                Files.createDirectories(report.getParent());
                Files.writeString(report, text);
                return text;
            } finally {
                acker.shutdownNow();
                central.close();
            }
        }
    }

    private void applied(String topic, byte[] payload, boolean changed) {
        if (!changed || !topic.contains("/alert/") || payload.length == 0) {
            return;
        }
        long now = micros(Instant.now());
        Map<String, String> m = Payloads.fields(new String(payload, StandardCharsets.UTF_8));
        String[] l = topic.split("/");
        String key = l[1] + "/" + l[3];
        if (m.get("state").equals("OPEN")) {
            opened.incrementAndGet();
            alertMicros.add(now - micros(Instant.parse(m.get("raisedAt"))));
            acker.execute(() -> {
                try {
                    ackSent.put(key, micros(Instant.now()));
                    central.acknowledge(l[1], l[3], "care centre");
                } catch (Exception e) {
                    ackFailures.incrementAndGet();
                }
            });
        } else if (m.get("state").equals("ACKNOWLEDGED")) {
            Long sent = ackSent.remove(key);
            if (sent != null) {
                ackMicros.add(now - sent);
            }
        }
    }

    private String report(Map<String, Long> sims, double wall, ProcStat b0, ProcStat b1, ProcStat s0, ProcStat s1,
            ProcStat f0, ProcStat f1, long[] peak) {
        Board.Totals t = central.board().totals();
        double perFlat = sims.get("published") / wall / o.flats();
        double size = (double) sims.get("bytes") / Math.max(1, sims.get("published"));
        StringBuilder b = new StringBuilder();
        b.append(String.format("MQTT load test, %s%n", Instant.now()));
        b.append(String.format("flats=%d (one MQTT connection each, simulated: SimFlats), run=%.0f s, heartbeat=%d s, "
                + "device state every %d ms, occupancy every %d s, alert every %d s per flat%n", o.flats(), wall,
                o.heartbeatSeconds(), o.stateMillis(), o.occupancySeconds(), o.alertSeconds()));
        b.append(String.format("published (PUBACKed)=%d, failed=%d, per flat %.2f msg/s, mean %.0f bytes (topic+payload), "
                + "total %.0f msg/s%n", sims.get("published"), sims.get("failed"), perFlat, size, sims.get("published") / wall));
        b.append(String.format("board topics published=%d, read by the board=%d, lost=%d; bad=%d duplicates=%d flats seen=%d "
                + "(ignored: unknown flats=%d, unsigned=%d)%n",
                sims.get("boardTopics"), t.messages(), Math.max(0, sims.get("boardTopics") - t.messages()), t.bad(),
                t.duplicates(), t.flats(), t.unknownFlats(), t.unsigned()));
        b.append(String.format("alerts raised=%d, seen OPEN on the board=%d, lost=%d%n", sims.get("alerts"), opened.get(),
                sims.get("alerts") - opened.get()));
        b.append(String.format("alert latency flat→board: p50=%.1f ms p99=%.1f ms max=%.1f ms (n=%d)%n", pct(alertMicros, 50),
                pct(alertMicros, 99), pct(alertMicros, 100), alertMicros.size()));
        b.append(String.format("acknowledgement round trip board→flat→board: p50=%.1f ms p99=%.1f ms (n=%d, acks received by flats=%d, failed=%d)%n",
                pct(ackMicros, 50), pct(ackMicros, 99), ackMicros.size(), sims.get("acks"), ackFailures.get()));
        b.append(String.format("CPU (%% of one core): broker=%.1f board=%.1f flats=%.1f; peak RSS MB: broker=%.1f board=%.1f flats=%.1f%n",
                b1.cpuPercentSince(b0, wall), s1.cpuPercentSince(s0, wall), f1.cpuPercentSince(f0, wall), peak[0] / 1024.0,
                peak[1] / 1024.0, peak[2] / 1024.0));
        return b.toString();
    }

    private static void peak(long[] peak, long... pids) {
        for (int i = 0; i < pids.length; i++) {
            peak[i] = Math.max(peak[i], ProcStat.of(pids[i]).rssKb());
        }
    }

    private static double pct(List<Long> values, int p) {
        List<Long> v;
        synchronized (values) {
            v = new ArrayList<>(values);
        }
        if (v.isEmpty()) {
            return Double.NaN;
        }
        Collections.sort(v);
        int i = (int) Math.ceil(p / 100.0 * v.size()) - 1;
        return v.get(Math.max(0, Math.min(v.size() - 1, i))) / 1000.0;
    }

    private static long micros(Instant i) {
        return i.getEpochSecond() * 1_000_000L + i.getNano() / 1000;
    }

    private static Map<String, Long> parse(String stats) {
        Map<String, Long> m = new ConcurrentHashMap<>();
        for (String kv : stats.substring("SIMSTATS ".length()).split(" ")) {
            String[] p = kv.split("=");
            m.put(p[0], Long.parseLong(p[1]));
        }
        return m;
    }

    /** {@code LoadHarness <flats> <seconds> <heartbeatS> <stateMs> <alertS> <occupancyS> [report file]}. */
    public static void main(String[] a) throws Exception {
        Options o = new Options(Integer.parseInt(a[0]), Integer.parseInt(a[1]), Integer.parseInt(a[2]), Integer.parseInt(a[3]),
                Integer.parseInt(a[4]), Integer.parseInt(a[5]));
        System.out.print(new LoadHarness(o).run(Path.of(a.length > 6 ? a[6] : "target" + File.separator + "mqtt-load-report.txt")));
        System.exit(0);
    }
}
