package org.tinysep.inactivity.internal;

import java.lang.management.ManagementFactory;
import java.time.Instant;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 29, item 1: nanoseconds of the delivery thread per movement report that Inactivity Recognition spends (a
 * measuring tool, not a test: times are never asserted). Run it like the distribution, C1 only:
 * {@code java -XX:TieredStopAtLevel=1 -XX:+UseSerialGC -cp <test classpath> ...PerReportTiming [zone] [rounds]}.
 * Each round times the same loop twice: a movement sensor with Inactivity Recognition (LEARNED, placed sensor, a
 * report every 100 ms of platform time, no worn node) as its listener, and the floor: the same sensor and loop with
 * an empty listener. It prints ns per report of both, their difference, and bytes allocated per report.
 */
public final class PerReportTiming {

    private static final int REPORTS = 1_000_000;
    private static Instant now = Instant.parse("2026-11-23T09:00:00Z");

    private PerReportTiming() {
    }

    public static void main(String[] args) {
        ZoneId zone = ZoneId.of(args.length > 0 ? args[0] : "Europe/Zurich");
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 7;
        Fakes.Movement bath = new Fakes.Movement("m-bath");
        InactivityDevice device = device(zone, bath);
        Fakes.Movement empty = new Fakes.Movement("m-empty");
        empty.connect(new MovementListener() {
            @Override
            public void movementReported(MovementProvider source, MovementEvent movement) {
                // the floor: delivery and the loop, no work
            }
        });
        bath.report(true, now); // starts the watch
        double[] inact = new double[rounds];
        double[] floor = new double[rounds];
        double[] bytes = new double[rounds];
        for (int r = 0; r < rounds; r++) {
            floor[r] = loop(empty)[0];
            double[] d = loop(bath);
            inact[r] = d[0];
            bytes[r] = d[1] - loop(empty)[1];
        }
        Arrays.sort(inact);
        Arrays.sort(floor);
        Arrays.sort(bytes);
        System.out.printf("zone %s, %d rounds of %,d reports, state %s%n", zone, rounds, REPORTS, device.state());
        System.out.printf("inactivity ns/report: min %.1f median %.1f max %.1f%n", inact[0], inact[rounds / 2],
                inact[rounds - 1]);
        System.out.printf("floor      ns/report: min %.1f median %.1f max %.1f%n", floor[0], floor[rounds / 2],
                floor[rounds - 1]);
        System.out.printf("inactivity - floor (medians): %.1f ns/report; ratio to floor %.2f%n",
                inact[rounds / 2] - floor[rounds / 2], inact[rounds / 2] / floor[rounds / 2]);
        System.out.printf("bytes/report above the floor (median): %.1f%n", bytes[rounds / 2]);
    }

    /** @return ns per report and bytes allocated per report */
    private static double[] loop(Fakes.Movement sensor) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long b0 = mx.getThreadAllocatedBytes(id);
        long t0 = System.nanoTime();
        for (int i = 0; i < REPORTS; i++) {
            now = now.plusMillis(100);
            sensor.report(true, now);
        }
        long t1 = System.nanoTime();
        long b1 = mx.getThreadAllocatedBytes(id);
        return new double[] {(t1 - t0) / (double) REPORTS, (b1 - b0) / (double) REPORTS};
    }

    /** As the platform's placements: the room as a kept Optional, not a new one per question. */
    private static final class Tracked extends FakePlacements {
        private final Map<String, Optional<String>> kept = new HashMap<>();

        @Override
        public Optional<String> roomOf(String deviceUid) {
            Optional<String> room = kept.get(deviceUid);
            if (room == null || !Objects.equals(room.orElse(null), rooms.get(deviceUid))) {
                room = Optional.ofNullable(rooms.get(deviceUid));
                kept.put(deviceUid, room);
            }
            return room;
        }
    }

    private static InactivityDevice device(ZoneId zone, Fakes.Movement bath) {
        RecordingLogs logs = new RecordingLogs(() -> now);
        FakePlacements directory = new Tracked();
        InactivityDevice device = new InactivityDevice(
                new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
                directory, LimitTable.parse(120, "Bathroom=45", ""), new AlertMail(ZoneOffset.UTC),
                LimitPolicy.learned(new LearnedLimits(new HistoryLearner(zone, new SleepRule(21, 7, zone),
                        LearningSettings.defaults()))), null);
        directory.rooms.put("m-bath", "r-bath");
        directory.names.put("m-bath", "Bath sensor");
        device.use(new FakeHouse(new Room("r-bath", "Bathroom", "Bathroom", Set.of())));
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, now));
        device.watch(bath);
        return device;
    }
}
