package org.tinysep.simulator.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.flat.Flat;
import org.tinysep.simulator.flat.FlatLoader;
import org.tinysep.simulator.node.Target;
import org.tinysep.simulator.time.FakeSynchroniserPeer;
import org.tinysep.simulator.time.LockStepDriver;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;

/**
 * Flat A's demo day, 24 virtual hours in lock-step against a fake peer that answers DONE at once, with every
 * node's frames going to real (unread) UDP sockets on 127.0.0.1. Prints the wall time (a figure, not an assertion).
 */
class DemoDayLockStepTest {

    @Test
    void aWholeDemoDayInLockStep() throws Exception {
        Flat flat = FlatLoader.load("flat-a");
        long midnight = LocalDate.parse("2026-11-23").atStartOfDay(ZoneOffset.UTC).toEpochSecond();
        Instant from = Instant.ofEpochSecond(midnight);
        try (DatagramSocket amica = new DatagramSocket(0, InetAddress.getLoopbackAddress());
                DatagramSocket spots = new DatagramSocket(0, InetAddress.getLoopbackAddress());
                FakeSynchroniserPeer peer = new FakeSynchroniserPeer("EXTERNAL");
                SyncClient sync = new SyncClient(peer.address(), 2000);
                Simulation sim = new Simulation(flat, Simulation.scenario("demo-day", flat),
                        new Target(InetAddress.getLoopbackAddress(), amica.getLocalPort(), spots.getLocalPort()),
                        midnight, 1, 90, 0.002, e -> { })) {
            int[] changed = new int[1];
            long start = System.nanoTime();
            new LockStepDriver(sync, new VirtualClock(from), 5_000_000L).run(from, from.plusSeconds(86400), t -> {
                int c = sim.step(t);
                changed[0] += c > 0 ? 1 : 0;
                return c;
            });
            double wall = (System.nanoTime() - start) / 1e9;
            System.out.printf("24 h demo day in lock-step: %.1f s wall time (%d paced seconds of 86400)%n", wall, changed[0]);
            List<Instant> ticks = peer.ticks();
            assertEquals(86400, ticks.size());
            assertEquals(from.plusSeconds(86399), ticks.get(86399));
            List<String> trace = sim.world().trace();
            assertTrue(trace.stream().anyMatch(e -> e.endsWith("anna collapses in Bathroom")), trace.toString());
        }
    }
}
