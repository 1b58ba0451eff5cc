package org.tinysep.simulator.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.SocketTimeoutException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.simulator.replay.EventsCsv;
import org.tinysep.simulator.time.FakeSynchroniserPeer;

/**
 * A small recording replayed in lock-step against a fake Time Controller, its frames caught on a real UDP socket on
 * 127.0.0.1: every node's keep-alive comes first, every recorded change is sent once and in order (a zero-length
 * interval too), quiet stretches are skipped at {@code --rate changes} and played second by second at full rate.
 */
class ReplayRunnerTest {

    private static final String EVENTS = EventsCsv.HEADER + """

            2011-11-28T10:00:00,Kitchen PIR,Kitchen,motion,ON
            2011-11-28T10:00:00,Kitchen PIR,Kitchen,motion,OFF
            2011-11-28T10:00:30,Front,Hall,door,OPEN
            2011-11-28T10:00:31,Front,Hall,door,CLOSE
            2011-11-28T10:05:00,Kitchen PIR,Kitchen,motion,ON
            2011-11-28T10:05:04,Kitchen PIR,Kitchen,motion,OFF
            """;

    @TempDir
    Path dir;

    @Test
    void changesOnlySendsEveryChangeInOrderAndSkipsQuietSeconds() throws Exception {
        Played played = play("changes");

        assertEquals(6, played.result().sent());
        Replay replay = played.result().replay();
        assertEquals(Replay.LEAD_SECONDS + 304 + Replay.TAIL_SECONDS,
                replay.untilSecond() - replay.fromSecond());
        List<Instant> ticks = played.ticks();
        assertTrue(ticks.size() < 200, "quiet seconds are skipped: " + ticks.size() + " ticks");
        for (int i = 1; i < ticks.size(); i++) {
            long step = ticks.get(i).getEpochSecond() - ticks.get(i - 1).getEpochSecond();
            assertTrue(step >= 1 && step <= ReplayRunner.QUIET_STEP, "tick step " + step + " at " + i);
        }
        assertTrue(ticks.contains(Instant.ofEpochSecond(replay.virtualSecond(LocalDateTime.parse("2011-11-28T10:00:31")))),
                "the door's closing second is played");

        Map<String, List<String>> byNode = byNode(played.frames());
        assertEquals("keep-alive", byNode.get("1.100").get(0), "the PIR announces itself first");
        assertEquals("keep-alive", byNode.get("1.101").get(0), "the door announces itself first");
        assertEquals(List.of("motion=true", "motion=false", "motion=true", "motion=false"),
                byNode.get("1.100").stream().filter(f -> !f.equals("keep-alive")).toList());
        assertEquals(List.of("open=true", "open=false"),
                byNode.get("1.101").stream().filter(f -> !f.equals("keep-alive")).toList());
    }

    @Test
    void fullRateRepeatsTheStateEverySecondItIsDue() throws Exception {
        Played played = play("full");
        long seconds = played.result().replay().untilSecond() - played.result().replay().fromSecond();
        assertEquals(seconds, played.ticks().size(), "every second is played");
        Map<String, List<String>> byNode = byNode(played.frames());
        long doorReports = byNode.get("1.101").stream().filter(f -> f.startsWith("open=")).count();
        long pirReports = byNode.get("1.100").stream().filter(f -> f.startsWith("motion=")).count();
        assertEquals(seconds + 2, doorReports, "a reed switch reports every second, plus its 2 changes");
        assertEquals(seconds / 2 + 4, pirReports, "a PIR reports every 2 s, plus its 4 changes");
    }

    /** The evaluation harness: a collapse deletes the 12 h after it, and the replay must still play them (quiet). */
    @Test
    void endPlaysOnQuietlyUntilTheGivenRecordedTime() throws Exception {
        Played played = play("changes", "--end", "2011-11-28T22:05:04");
        long end = played.result().replay().virtualSecond(LocalDateTime.parse("2011-11-28T22:05:04"));
        Instant last = played.ticks().get(played.ticks().size() - 1);
        assertEquals(6, played.result().sent());
        assertTrue(last.getEpochSecond() >= end - ReplayRunner.QUIET_STEP && last.getEpochSecond() < end,
                "played on to 12 h after the last event: last tick " + last + ", end " + Instant.ofEpochSecond(end));
        assertThrows(IllegalArgumentException.class, () -> Options.parse(new String[] {"--end", "tomorrow"}));
    }

    @Test
    void aMissingRecordingIsAClearError() {
        Exception e = assertThrows(java.io.IOException.class,
                () -> Run.replay("--replay", dir.resolve("nope.csv").toString(), "--lockstep"));
        assertTrue(e.getMessage().contains("nope.csv"), e.getMessage());
    }

    /** What one lock-step replay of {@link #EVENTS} did: its result, the frames the radio got, the synchroniser's ticks. */
    private record Played(ReplayResult result, List<String> frames, List<Instant> ticks) {
    }

    /** Replays {@link #EVENTS} at {@code rate} (and {@code more} options) to a radio socket and a synchroniser peer. */
    private Played play(String rate, String... more) throws Exception {
        Path file = Files.writeString(dir.resolve("events.csv"), EVENTS);
        try (DatagramSocket radio = new DatagramSocket(0, InetAddress.getLoopbackAddress());
                FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL")) {
            Future<List<String>> received = collect(radio);
            List<String> args = new ArrayList<>(List.of(args(file, radio, peer, rate)));
            args.addAll(List.of(more));
            ReplayResult r = Run.replay(args.toArray(String[]::new));
            return new Played(r, received.get(), peer.ticks());
        }
    }

    private static String[] args(Path file, DatagramSocket radio, FakeSynchroniserPeer peer, String rate) {
        return new String[] {"--replay", file.toString(), "--lockstep", "--rate", rate, "--pace-ms", "1",
                "--amica-port", Integer.toString(radio.getLocalPort()), "--sync-port",
                Integer.toString(peer.address().getPort()), "--progress", "100000"};
    }

    /** Collects frames on another thread (the socket's buffer would overflow) until 1 s of silence. */
    private static Future<List<String>> collect(DatagramSocket radio) {
        ExecutorService e = Executors.newSingleThreadExecutor();
        Future<List<String>> f = e.submit(() -> receive(radio));
        e.shutdown();
        return f;
    }

    /** Drains the socket: {@code "<address> <what>"} per frame, in arrival order. */
    private static List<String> receive(DatagramSocket radio) throws Exception {
        radio.setSoTimeout(5000); // the replay starts; then 1 s of silence ends it
        List<String> out = new ArrayList<>();
        byte[] buf = new byte[512];
        while (true) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                radio.receive(p);
            } catch (SocketTimeoutException e) {
                return out;
            }
            radio.setSoTimeout(1000);
            AmicaFrame f = AmicaCodec.decode(p.getData(), 0, p.getLength());
            Object payload = AmicaPayloads.decode(f.payload());
            String what = payload instanceof KeepAlive ? "keep-alive"
                    : payload instanceof MotionDetection m ? "motion=" + m.detected()
                    : payload instanceof ReedSwitchStatus s ? "open=" + s.open()
                    : payload.toString();
            out.add(f.sender() + " " + what);
        }
    }

    private static Map<String, List<String>> byNode(List<String> frames) {
        Map<String, List<String>> m = new TreeMap<>();
        for (String f : frames) {
            int sp = f.indexOf(' ');
            m.computeIfAbsent(f.substring(0, sp), k -> new ArrayList<>()).add(f.substring(sp + 1));
        }
        return m;
    }
}
