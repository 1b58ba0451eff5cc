package org.tinysep.itests.lifecycle;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.Bundle;
import org.osgi.framework.Version;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.itests.Topology;

/**
 * Issue 6 point 3: AmICA Movement is updated to a new build (same classes, higher Bundle-Version, a real
 * {@code Bundle.update(InputStream)}) while movement frames stream in over UDP at thousands per second. Its devices
 * come back with the same UIDs, Flat Occupancy, Follow-me Light and Inactivity Recognition reconnect by themselves,
 * and no frame the radio receives after the swap completes is lost — nor, since the bus devices hold payloads for a
 * replacement listener (busradio.base {@code Handover}), one received during the swap. Prints, per swap, the swap
 * time, how many frames arrived during it and how many reached no movement consumer (docs/runtime-changes.md).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class HotUpdateUnderLoadTest extends TinySepTestSupport {

    static final String MOVEMENT_BSN = "org.tinysep.amica.movement";
    private static final int NODES = 8;
    private static final String LIGHT = "1.60"; // the simple light Follow-me Light needs
    private static final int FRAMES_PER_SECOND = 5000;
    private static final int SWAPS = 3;
    private static final Duration GRAPH_BACK = Duration.ofSeconds(60);
    private static final Duration AFTER_SWAP = Duration.ofMillis(1500);
    private static final List<String> CONSUMERS = List.of("FlatOccupancy", "FollowMeLight", "InactivityRecognition");

    @Test
    public void movementDriverUpdatedUnderLoadComesBackAndLosesNothingAfterTheSwap() throws Exception {
        int port = udpPortOf("BusRadioAmicaUdp");
        Bundle movement = bundle(MOVEMENT_BSN);
        List<String> report = new ArrayList<>();
        ExecutorService sender = Executors.newSingleThreadExecutor();
        try (ConsumerTaps taps = new ConsumerTaps(context)) {
            for (int run = 1; run <= SWAPS; run++) {
                report.add(swapOnce(run, port, movement, taps, sender));
            }
        } finally {
            sender.shutdownNow();
        }
        String figures = String.join("\n", report);
        System.out.println("Hot update of " + MOVEMENT_BSN + " under load (" + NODES + " nodes, "
                + FRAMES_PER_SECOND + " frames/s):\n" + figures);
        log.info("Hot update figures:\n{}", figures);
    }

    private String swapOnce(int run, int port, Bundle movement, ConsumerTaps taps, ExecutorService sender)
            throws Exception {
        MovementFlood flood = new MovementFlood(port, NODES, 40, FRAMES_PER_SECOND, 200_000, 30_000);
        long kernelBefore = kernelDrops(port);
        flood.keepAlives(Integer.parseInt(LIGHT.substring(2)));
        await(TIMEOUT, () -> movementUids().size() == NODES, NODES + " AmicaMovement devices");
        await(TIMEOUT, () -> CONSUMERS.stream().allMatch(c -> consumes(Topology.of(context), c)),
                "each of " + CONSUMERS + " connected to all " + NODES + " movement devices");
        // the light's edges too: a graph taken before the light connected to its bus device and Follow-me Light to
        // the light is not the whole graph (a run once found them "extra" after the swap)
        await(TIMEOUT, () -> Topology.of(context).containsAll(List.of(
                "AmicaSimpleLight@" + LIGHT + " <- BusRadioAmicaProvider of BusRadioAmicaUdp@" + LIGHT,
                "FollowMeLight <- SimpleLightProvider of AmicaSimpleLight@" + LIGHT)), "the light " + LIGHT + " connected");
        Set<String> graphBefore = Topology.of(context);
        Set<String> uidsBefore = movementUids();
        if (run == 1) {
            log.info("Device graph before the swaps:\n{}", String.join("\n", graphBefore));
        }
        DeliveryLedger ledger = new DeliveryLedger();
        taps.record(ledger);
        Future<?> sending = sender.submit(flood);
        await(TIMEOUT, () -> ledger.radioCount() >= FRAMES_PER_SECOND / 2, "the stream to reach the platform");

        byte[] build = NewBuild.withVersion(movement.getLocation(), "0.1." + (100 + run) + ".swap");
        long t0 = System.nanoTime();
        movement.update(new ByteArrayInputStream(build));
        long returned = System.nanoTime();
        for (Set<String> now = Topology.of(context); !now.equals(graphBefore); now = Topology.of(context)) {
            // a generous bound, not a speed assertion: the swap time is a reported figure (a CI run once failed a
            // 10 s bound); polling every 2 ms leaves the CPUs to the swap itself
            assertTrue("device graph back within 60 s after update(); missing " + minus(graphBefore, now)
                    + ", extra " + minus(now, graphBefore), System.nanoTime() - t0 < GRAPH_BACK.toNanos());
            Thread.sleep(2);
        }
        long done = System.nanoTime();
        long radioAtDone = ledger.radioCount();
        await(TIMEOUT, () -> ledger.radioCount() - radioAtDone >= FRAMES_PER_SECOND * AFTER_SWAP.toMillis() / 1000,
                "frames after the swap");
        flood.stop();
        sending.get(30, TimeUnit.SECONDS);
        try {
            await(TIMEOUT, () -> ledger.radioCount() + kernelDrops(port) - kernelBefore == flood.sent(),
                    "every frame sent to reach the radio or be counted as dropped by the kernel");
        } catch (AssertionError e) {
            log.warn("UDP lost {} of {} frames before the radio", flood.sent() - ledger.radioCount(), flood.sent());
        }
        long kernel = kernelDrops(port) - kernelBefore;

        assertEquals("new build active", new Version(0, 1, 100 + run, "swap"), movement.getVersion());
        assertEquals(Bundle.ACTIVE, movement.getState());
        assertEquals("same device UIDs after the update", uidsBefore, movementUids());
        assertEquals("consumers reconnected by themselves", graphBefore, Topology.of(context));
        List<DeliveryLedger.Received> dropped = ledger.dropped();
        long droppedAfter = dropped.stream().filter(r -> r.nanos() >= done).count();
        long droppedBefore = dropped.stream().filter(r -> r.nanos() < t0).count();
        String line = String.format(Locale.ROOT, "swap %d: update() %.1f ms, graph back %.1f ms after update(); "
                + "frames sent %d, received by the radio %d (during the swap %d), delivered to movement consumers %d; "
                + "dropped %d (before update() %d, during the swap %d, after the swap %d); dropped by the kernel at the "
                + "radio's full socket buffer %d", run,
                (returned - t0) / 1e6, (done - t0) / 1e6, flood.sent(), ledger.radioCount(),
                ledger.radioBetween(t0, done), ledger.consumerCount(), dropped.size(), droppedBefore,
                dropped.size() - droppedBefore - droppedAfter, droppedAfter, kernel);
        log.info(line);
        // a CPU-starved machine (a CI run beside other work) can overflow the socket buffer before the radio reads:
        // those frames never reached the platform and are counted by the kernel (/proc/net/udp and udp6); every
        // frame the radio did receive must still reach its consumers (below)
        assertEquals("UDP: frames sent = frames received by the radio + dropped by the kernel: " + line,
                flood.sent(), ledger.radioCount() + kernel);
        assertEquals("frames received after the swap completed but delivered to no consumer: " + line, 0,
                droppedAfter);
        assertEquals("frames received before update() but not delivered: " + line, 0, droppedBefore);
        assertEquals("frames received during the swap but not delivered (the bus devices hold them for the new "
                + "AmicaMovement devices): " + line, 0, dropped.size());
        return line;
    }

    /**
     * @return datagrams the kernel dropped at the port's full socket buffer so far (the last column of
     *         /proc/net/udp and udp6, where the JVM's dual-stack sockets are listed), 0 where it cannot tell. The
     *         simulator's {@code KernelDrops} says the same but is not provisioned in this framework.
     */
    private static long kernelDrops(int port) {
        String local = String.format(Locale.ROOT, ":%04X", port);
        long drops = 0;
        for (String table : List.of("/proc/net/udp", "/proc/net/udp6")) {
            try {
                for (String line : java.nio.file.Files.readAllLines(java.nio.file.Path.of(table))) {
                    String[] f = line.trim().split("\\s+");
                    if (f.length > 12 && f[1].endsWith(local)) {
                        drops += Long.parseLong(f[f.length - 1]);
                    }
                }
            } catch (java.io.IOException | RuntimeException e) {
                // not Linux, or the table changed shape: counts as no drops
            }
        }
        return drops;
    }

    private static Set<String> minus(Set<String> a, Set<String> b) {
        Set<String> d = new TreeSet<>(a);
        d.removeAll(b);
        return d;
    }

    /** @return whether {@code consumer} is connected to the movement provider of every flooding node */
    private static boolean consumes(Set<String> graph, String consumer) {
        return graph.stream().filter(l -> l.startsWith(consumer + " <- MovementProvider of AmicaMovement@1.")).count()
                == NODES;
    }

    private Set<String> movementUids() {
        return Topology.of(context).stream().filter(l -> l.startsWith("AmicaMovement@") && !l.contains(" <- "))
                .map(l -> Topology.uid(context, "AmicaMovement", l.substring(l.indexOf('@') + 1)))
                .collect(Collectors.toCollection(TreeSet::new));
    }

    private Bundle bundle(String bsn) {
        for (Bundle b : context.getBundles()) {
            if (bsn.equals(b.getSymbolicName())) {
                return b;
            }
        }
        throw new AssertionError("no bundle " + bsn);
    }
}
