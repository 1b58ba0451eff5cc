package org.tinysep.followmelight.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.Reporter;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Harness, not a test: nanoseconds Follow Me Light spends (1) per movement report in a lit room and (2) per
 * lighting of a room and its going dark again (the packet → light command path), with one light per room among
 * 40 and among 400 lights (the benchmark's house shape), against the floor of an empty listener in the same run.
 * Run it as the distribution runs (C1 only), e.g. {@code java -XX:TieredStopAtLevel=1 -cp <test classpath>
 * org.tinysep.followmelight.internal.FollowMeReportBench [reports per round] [rounds]}.
 */
public final class FollowMeReportBench {

    private static final Instant T0 = Instant.parse("2026-11-22T19:00:00Z");
    private static volatile Instant now = T0;
    private static int events;
    private static final EventLog LOG = new EventLog() {
        @Override
        public void record(EventKind kind, String origin, String message) {
            events++;
        }

        @Override
        public List<EventEntry> recent(int max) {
            return List.of();
        }
    };

    private FollowMeReportBench() {
    }

    /** A flat of {@code rooms} rooms, one light and one sensor in each, occupied. */
    private record Flat(FollowMeDevice device, Fakes.Movement[] sensors) {
        static Flat of(int rooms) {
            CountingPlacements directory = new CountingPlacements();
            FollowMeDevice d = new FollowMeDevice(new DriverContext(null, "d", "FollowMeLight",
                    new Reporter(() -> LOG, () -> null), new PlatformClock(() -> now)), directory,
                    Duration.ofSeconds(30), Percent.of(100));
            Fakes.Movement[] sensors = new Fakes.Movement[rooms];
            for (int r = 0; r < rooms; r++) {
                directory.place("light-" + r, "r" + r);
                directory.place("sensor-" + r, "r" + r);
                d.control(new QuietLight("light-" + r));
                sensors[r] = new Fakes.Movement("sensor-" + r);
                d.use(sensors[r]);
            }
            d.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
            return new Flat(d, sensors);
        }

        /** Lights room {@code r} and lets it go dark again. */
        void cycle(int r) {
            Instant at = now;
            device.movementReported(sensors[r], new MovementEvent(true, at));
            Instant later = at.plusSeconds(31);
            now = later;
            device.tick(later);
        }
    }

    public static void main(String[] args) {
        int calls = args.length > 0 ? Integer.parseInt(args[0]) : 2_000_000;
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 9;
        int cycles = Math.max(1000, calls / 200);
        Flat small = Flat.of(40);
        Flat large = Flat.of(400);
        MovementEvent report = new MovementEvent(true, T0.plusSeconds(1));
        small.device.movementReported(small.sensors[0], report); // r0 lit: later reports renew it
        MovementListener empty = (source, movement) -> { };
        double[][] m = new double[5][rounds];
        for (int r = -2; r < rounds; r++) { // two rounds of warm-up
            double[] x = {
                nsPerCall(empty, small.sensors[0], report, calls),
                nsPerCall(small.device, small.sensors[0], report, calls),
                nsPerCycle(null, cycles),
                nsPerCycle(small, cycles),
                nsPerCycle(large, cycles) };
            if (r >= 0) {
                for (int k = 0; k < x.length; k++) {
                    m[k][r] = x[k];
                }
            }
        }
        String[] names = {"floor (empty listener)", "report in a lit room", "floor of a cycle (time only)",
            "light + dark, 40 lights", "light + dark, 400 lights"};
        System.out.printf("reports/round %d, cycles/round %d, rounds %d, events %d, jvm %s%n", calls, cycles,
                rounds, events, java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments());
        double[] med = new double[m.length];
        for (int k = 0; k < m.length; k++) {
            Arrays.sort(m[k]);
            med[k] = m[k][rounds / 2];
            System.out.printf("%-30s median %9.1f ns, best %9.1f%n", names[k], med[k], m[k][0]);
        }
        System.out.printf("report in a lit room: %.2f x the floor, %.1f ns over it%n", med[1] / med[0],
                med[1] - med[0]);
        System.out.printf("lighting cycle: 40 lights %.0f ns, 400 lights %.0f ns over the floor (400/40: %.2f)%n",
                med[3] - med[2], med[4] - med[2], (med[4] - med[2]) / (med[3] - med[2]));
    }

    private static double nsPerCall(MovementListener l, Fakes.Movement source, MovementEvent report, int calls) {
        long t0 = System.nanoTime();
        for (int i = 0; i < calls; i++) {
            l.movementReported(source, report);
        }
        return (System.nanoTime() - t0) / (double) calls;
    }

    /** {@code flat} null: the cycle's own time arithmetic only. */
    private static double nsPerCycle(Flat flat, int cycles) {
        int rooms = flat == null ? 1 : flat.sensors.length;
        long t0 = System.nanoTime();
        for (int i = 0; i < cycles; i++) {
            if (flat == null) {
                Instant at = now;
                new MovementEvent(true, at);
                now = at.plusSeconds(31);
            } else {
                flat.cycle(i % rooms);
            }
        }
        return (System.nanoTime() - t0) / (double) cycles;
    }
}
