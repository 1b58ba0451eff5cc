package org.tinysep.simulator.time;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The lock-step client against a fake synchroniser peer over real UDP on 127.0.0.1. */
class LockStepTest {

    @Test
    void helloReportsThePlatformTimeAndMode() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("REAL"); SyncClient c = new SyncClient(peer.address(), 2000)) {
            Welcome w = c.hello();
            assertEquals(Instant.parse("2026-11-22T12:00:00Z"), w.platformTime());
            assertFalse(w.external());
        }
    }

    @Test
    void ticksAndByeAreSignedWithTheKeyForTheSessionOfWelcome(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path keyFile = dir.resolve("sync.key");
        java.nio.file.Files.writeString(keyFile, "a-known-test-key-0123456789\n");
        byte[] key = SyncClient.readKey(keyFile);
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL");
                SyncClient c = new SyncClient(peer.address(), 2000, key)) {
            c.hello();
            c.tick(Instant.parse("2026-11-23T08:00:00Z"));
            c.bye();
            javax.crypto.Mac mac = javax.crypto.Mac.getInstance("HmacSHA256");
            mac.init(new javax.crypto.spec.SecretKeySpec("a-known-test-key-0123456789".getBytes(), "HmacSHA256"));
            String tick = "TICK 1 2026-11-23T08:00:00Z";
            String expected = java.util.HexFormat.of().formatHex(
                    mac.doFinal((FakeSynchroniserPeer.SESSION + " " + tick).getBytes()));
            assertEquals(List.of("HELLO", tick + " " + expected, "BYE 2 " + java.util.HexFormat.of().formatHex(
                    mac.doFinal((FakeSynchroniserPeer.SESSION + " BYE 2").getBytes()))), peer.requests);
        }
    }

    @Test
    void theDriverTicksEverySecondInOrderBeforeItsFrames() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL"); SyncClient c = new SyncClient(peer.address(), 2000)) {
            assertTrue(c.hello().external());
            Instant from = Instant.parse("2026-11-23T08:00:00Z");
            VirtualClock clock = new VirtualClock(from);
            List<String> log = new ArrayList<>();
            new LockStepDriver(c, clock, 1_000_000).run(from, from.plusSeconds(100), t -> {
                log.add(t + " step, platform at " + (peer.ticks().isEmpty() ? "-" : peer.ticks().get(peer.ticks().size() - 1)));
                return t.getEpochSecond() % 10 == 0 ? 1 : 0;
            });
            List<Instant> ticks = peer.ticks();
            assertEquals(100, ticks.size());
            for (int i = 0; i < 100; i++) {
                assertEquals(from.plusSeconds(i), ticks.get(i));
            }
            assertEquals(from.plusSeconds(5) + " step, platform at " + from.plusSeconds(5), log.get(5),
                    "each second's frames go out after its TICK's DONE, so the radio stamps them with that second");
            assertEquals(from.plusSeconds(99), clock.now());
        }
    }

    @Test
    void aReplaySkipsToTheNextSecondItsNextSecondFunctionNames() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL"); SyncClient c = new SyncClient(peer.address(), 2000)) {
            assertTrue(c.hello().external());
            Instant from = Instant.parse("2026-11-23T08:00:00Z");
            List<Instant> stepped = new ArrayList<>();
            long played = new LockStepDriver(c, new VirtualClock(from), 0).run(from, from.plusSeconds(100), t -> {
                stepped.add(t);
                return 0;
            }, t -> t + 10);
            assertEquals(10, played);
            assertEquals(stepped, peer.ticks(), "every played second is ticked, and only those");
            assertEquals(from.plusSeconds(90), stepped.get(9));
        }
    }

    @Test
    void aLostDoneIsRetriedWithTheSameSequenceAndInstant() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL"); SyncClient c = new SyncClient(peer.address(), 300)) {
            peer.loseFirstDone();
            Instant t = Instant.parse("2026-11-23T08:00:00Z");
            c.tick(t);
            c.tick(t.plusSeconds(1));
            assertEquals(List.of("TICK 1 " + t, "TICK 1 " + t, "TICK 2 " + t.plusSeconds(1)), peer.requests);
            assertEquals(2, peer.ticks().size(), "the retransmission did not fire again");
        }
    }

    /**
     * A new run whose socket got the port of an earlier run (the kernel reuses ephemeral ports) is in that run's
     * session: the platform refuses sequence number 1 as replayed. The client continues above the last accepted one.
     */
    @Test
    void aSessionInheritedFromAnEarlierRunOnTheSamePortContinuesAboveItsLastSequence() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL"); SyncClient c = new SyncClient(peer.address(), 2000)) {
            peer.lastAccepted(6491);
            Instant t = Instant.parse("2026-11-23T08:00:00Z");
            c.hello();
            c.tick(t);
            c.tick(t.plusSeconds(1));
            c.bye();
            assertEquals(List.of("HELLO", "TICK 1 " + t, "TICK 6492 " + t, "TICK 6493 " + t.plusSeconds(1), "BYE 6494"),
                    peer.requests);
            assertEquals(2, peer.ticks().size());
        }
    }

    @Test
    void anErrorAnswerStopsWithThePlatformsText() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL"); SyncClient c = new SyncClient(peer.address(), 2000)) {
            IOException e = assertThrows(IOException.class, () -> c.tick(Instant.parse("2020-01-01T00:00:00Z")));
            assertTrue(e.getMessage().contains("backwards"), e.getMessage());
        }
    }

    @Test
    void helloWaitsForAPlatformThatIsStillStarting() throws Exception {
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("REAL"); SyncClient c = new SyncClient(peer.address(), 300)) {
            assertFalse(c.hello(0).external(), "no wait: the first answer");
            long start = System.nanoTime();
            assertFalse(c.hello(1).external(), "still REAL after the wait: the caller reports it");
            assertTrue(System.nanoTime() - start >= 1_000_000_000L, "asked again for the whole second");
            assertTrue(peer.requests.size() >= 3, "asked again: " + peer.requests);
        }
    }

    @Test
    void noPeerGivesAClearMessage() throws Exception {
        java.net.InetSocketAddress nobody;
        try (FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL")) {
            nobody = peer.address();
        }
        try (SyncClient c = new SyncClient(nobody, 100)) {
            IOException e = assertThrows(IOException.class, c::hello);
            assertTrue(e.getMessage().contains("no answer to 'HELLO'"), e.getMessage());
        }
    }

    @Test
    void realTimeRunsAtTheGivenSpeed() throws Exception {
        Instant from = Instant.parse("2026-11-23T08:00:00Z");
        List<Instant> seen = new ArrayList<>();
        long start = System.nanoTime();
        new RealTimeDriver(new VirtualClock(from), 100).run(from, from.plusSeconds(20), t -> {
            seen.add(t);
            return 0;
        });
        assertEquals(20, seen.size());
        assertTrue(System.nanoTime() - start >= 190_000_000L, "20 virtual seconds at speed 100 take at least 0.19 s");
    }
}
