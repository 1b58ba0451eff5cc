package org.tinysep.simulator.node;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.simulator.cli.Simulation;
import org.tinysep.simulator.flat.Flat;
import org.tinysep.simulator.flat.FlatLoader;
import org.tinysep.simulator.person.SyntheticRecordings;
import org.tinysep.simulator.time.FakeSynchroniserPeer;
import org.tinysep.simulator.time.LockStepDriver;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/**
 * Issue 26 item 7: Anna wears a person node in the demo flat. Over real UDP on 127.0.0.1: while she moves about it
 * sends a moving summary every 2 s and no burst; her collapse is a fall (a burst around a peak of 2 g or more, then
 * still summaries lying); away, it is silent; without the pendant ({@code --no-pendant}) it does not exist.
 */
class PendantNodeTest {

    private static final String PENDANT = "0014.4F01.0000.0A04";
    private static final long MIDNIGHT = LocalDate.parse("2026-11-23").atStartOfDay(ZoneOffset.UTC).toEpochSecond();

    @TempDir
    Path dir;

    @Test
    void theShippedFallRecordingIsTheSyntheticOneItsProvenanceNames() throws Exception {
        SyntheticRecordings.write(dir, "SX01", 5);
        byte[] written = gunzip(Files.newInputStream(dir.resolve("SX01/" + PendantNode.FALL)));
        byte[] shipped = gunzip(PendantNode.class.getResourceAsStream("/recordings/" + PendantNode.FALL));
        assertTrue(written.length > 50_000 && java.util.Arrays.equals(written, shipped),
                "recordings/" + PendantNode.FALL + " is SyntheticRecordings.write(folder, \"SX01\", 5)'s F01");
    }

    @Test
    void annasCollapseIsAFallOnHerPendant() throws Exception {
        List<SunSpotPayload> frames = play(FlatLoader.load("flat-a"), "13:50", "14:10");
        int burst = firstBurst(frames);
        assertTrue(burst > 100, "moving summaries first, then the fall's burst: " + burst);
        List<MovementSummaryReport> before = summaries(frames.subList(0, burst));
        assertTrue(before.stream().allMatch(s -> s.peakMg() < 2000 && s.magnitudeSdMg() > 50),
                "moving about, never near 2 g: " + before.subList(0, 3));
        List<BurstChunk> chunks = frames.stream().filter(f -> f instanceof BurstChunk).map(f -> (BurstChunk) f)
                .toList();
        assertEquals(5, chunks.size(), "one standard burst (150 samples in 5 chunks)");
        double peak = chunks.stream().flatMap(c -> c.samples().stream())
                .mapToDouble(a -> Math.sqrt((double) a.xMg() * a.xMg() + (double) a.yMg() * a.yMg() + (double) a.zMg() * a.zMg()))
                .max().orElse(0);
        assertTrue(peak >= 3000, "the impact: " + peak);
        List<MovementSummaryReport> after = summaries(frames.subList(burst, frames.size()));
        List<MovementSummaryReport> lying = after.subList(after.size() - 100, after.size());
        assertTrue(lying.stream().allMatch(s -> s.magnitudeSdMg() <= 50 && s.mean().zMg() > 900),
                "then lying still on her back: " + lying.subList(0, 3));
        int total = summaries(frames).size();
        assertTrue(total >= 590 && total <= 605, "a summary every 2 s over 20 min: " + total);
    }

    /**
     * In lock-step the fall's burst leaves at its own instants, milliseconds kept: the driver TICKs the platform to
     * each chunk's instant inside the second (so the radio stamps the burst with its trigger, not the whole second
     * it fell in), and only to those: the summaries end on whole seconds.
     */
    @Test
    void inLockStepTheFallsBurstIsTickedToItsOwnMilliseconds() throws Exception {
        Flat flat = FlatLoader.load("flat-a");
        long a = MIDNIGHT + LocalTime.parse("13:58").toSecondOfDay();
        long b = MIDNIGHT + LocalTime.parse("14:06").toSecondOfDay();
        try (Radio amica = new Radio(); Radio spots = new Radio();
                FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL");
                SyncClient sync = new SyncClient(peer.address(), 2000);
                Simulation sim = new Simulation(flat, Simulation.scenario("demo-day", flat),
                        new Target(InetAddress.getLoopbackAddress(), amica.port(), spots.port()), MIDNIGHT, 1, 90, 0,
                        e -> { }, true)) {
            for (long t = MIDNIGHT; t < a; t++) {
                sim.rehearse(t);
            }
            sync.hello();
            long played = new LockStepDriver(sync, new VirtualClock(Instant.ofEpochSecond(a)), 0)
                    .run(Instant.ofEpochSecond(a), Instant.ofEpochSecond(b), sim.stepper());
            List<Instant> ticks = peer.ticks();
            List<Instant> inside = ticks.stream().filter(t -> t.getNano() != 0).toList();
            assertEquals(played, ticks.size());
            assertEquals(b - a, ticks.size() - inside.size(), "every whole second once: " + inside);
            assertTrue(!inside.isEmpty() && inside.size() <= 5, "the burst's 5 chunks, each at its instant "
                    + "(one may fall on a whole second): " + inside);
            assertTrue(!inside.get(inside.size() - 1).isAfter(inside.get(0).plusMillis(1980)),
                    "all within the burst's 2 s after its trigger: " + inside);
            assertTrue(inside.get(0).getNano() % 20_000_000 == 0, "on the node's 20 ms sample grid: " + inside);
        }
    }

    @Test
    void awayOrWithoutThePendantNothingIsSent() throws Exception {
        assertEquals(List.of(), play(FlatLoader.load("flat-a"), "09:00", "09:10"), "Anna is out shopping");
        assertEquals(List.of(), play(FlatLoader.load("flat-a").withoutPersonNodes(), "13:50", "14:10"));
    }

    /** @return the pendant's payloads, in the order sent, from {@code from} to {@code until} of the demo day */
    private static List<SunSpotPayload> play(Flat flat, String from, String until) throws Exception {
        long a = MIDNIGHT + LocalTime.parse(from).toSecondOfDay();
        long b = MIDNIGHT + LocalTime.parse(until).toSecondOfDay();
        try (Radio amica = new Radio(); Radio spots = new Radio();
                Simulation sim = new Simulation(flat, Simulation.scenario("demo-day", flat),
                        new Target(InetAddress.getLoopbackAddress(), amica.port(), spots.port()), MIDNIGHT, 1, 90, 0,
                        e -> { })) {
            for (long t = MIDNIGHT; t < a; t++) {
                sim.rehearse(t);
            }
            for (long t = a; t < b; t++) {
                sim.step(Instant.ofEpochSecond(t));
            }
            // the fixed Sun SPOTs report too: wait for the last second's frames, then keep the pendant's
            Thread.sleep(300);
            List<SunSpotPayload> out = new ArrayList<>();
            for (Radio.Datagram d : spots.received()) {
                SunSpotFrame f = SunSpotCodec.decode(d.bytes(), 0, d.bytes().length);
                if (f.source().toString().equalsIgnoreCase(PENDANT)) {
                    out.add(SunSpotPayloads.decode(f.payload()));
                }
            }
            return out;
        }
    }

    private static int firstBurst(List<SunSpotPayload> frames) {
        for (int i = 0; i < frames.size(); i++) {
            if (frames.get(i) instanceof BurstChunk) {
                return i;
            }
        }
        return -1;
    }

    private static List<MovementSummaryReport> summaries(List<SunSpotPayload> frames) {
        return frames.stream().filter(f -> f instanceof MovementSummaryReport).map(f -> (MovementSummaryReport) f)
                .toList();
    }

    private static byte[] gunzip(InputStream in) throws Exception {
        try (InputStream z = new GZIPInputStream(in); ByteArrayOutputStream out = new ByteArrayOutputStream()) {
            z.transferTo(out);
            return out.toByteArray();
        }
    }
}
