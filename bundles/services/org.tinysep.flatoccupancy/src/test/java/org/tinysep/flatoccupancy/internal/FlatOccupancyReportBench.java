package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.Reporter;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Harness, not a test: nanoseconds Flat Occupancy spends per movement report that changes nothing (an occupied
 * flat, the front door closed long ago), against the floor of an empty listener called the same way in the same
 * run. Run it as the distribution runs (C1 only), e.g.
 * {@code java -XX:TieredStopAtLevel=1 -cp <test classpath> org.tinysep.flatoccupancy.internal.FlatOccupancyReportBench
 * [calls per round] [rounds]}; it prints the median and the best round of each, and their ratio.
 */
public final class FlatOccupancyReportBench {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");
    private static volatile Instant now = T0;
    private static int events;

    private FlatOccupancyReportBench() {
    }

    public static void main(String[] args) {
        int calls = args.length > 0 ? Integer.parseInt(args[0]) : 2_000_000;
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 9;
        EventLog log = new EventLog() {
            @Override
            public void record(EventKind kind, String origin, String message) {
                events++;
            }

            @Override
            public List<EventEntry> recent(int max) {
                return List.of();
            }
        };
        FlatOccupancyDevice flat = new FlatOccupancyDevice(new DriverContext(null, "d", "FlatOccupancy",
                new Reporter(() -> log, () -> null), new PlatformClock(() -> now)), Duration.ofMinutes(10),
                Duration.ofSeconds(10));
        MovementProvider hall = Fixtures.movement();
        flat.doorChanged(Fixtures.door("front"), OpenState.OPEN, T0);
        flat.doorChanged(Fixtures.door("front"), OpenState.CLOSED, T0.plusSeconds(5));
        now = T0.plusSeconds(60);
        MovementEvent report = new MovementEvent(true, now);
        MovementListener empty = (source, movement) -> { };
        double[] floor = new double[rounds];
        double[] subject = new double[rounds];
        for (int r = -2; r < rounds; r++) { // two rounds of warm-up
            double f = nsPerCall(empty, hall, report, calls);
            double s = nsPerCall(flat, hall, report, calls);
            if (r >= 0) {
                floor[r] = f;
                subject[r] = s;
            }
        }
        Arrays.sort(floor);
        Arrays.sort(subject);
        double fm = floor[rounds / 2];
        double sm = subject[rounds / 2];
        System.out.printf("calls/round %d, rounds %d, events %d, jvm %s%n", calls, rounds, events,
                java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments());
        System.out.printf("floor (empty listener): median %.1f ns/report, best %.1f%n", fm, floor[0]);
        System.out.printf("FlatOccupancy:          median %.1f ns/report, best %.1f%n", sm, subject[0]);
        System.out.printf("ratio to floor %.2f x; over the floor %.1f ns/report%n", sm / fm, sm - fm);
    }

    private static double nsPerCall(MovementListener l, MovementProvider source, MovementEvent report, int calls) {
        long t0 = System.nanoTime();
        for (int i = 0; i < calls; i++) {
            l.movementReported(source, report);
        }
        return (System.nanoTime() - t0) / (double) calls;
    }
}
