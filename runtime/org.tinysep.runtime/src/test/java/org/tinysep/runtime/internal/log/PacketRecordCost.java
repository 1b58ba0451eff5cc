package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;

/**
 * What {@link PacketLog#record} costs the receive thread (issue 29, item 1), in CPU time of the recording thread,
 * beside its floor in the same run: an empty {@code record} through the same interface. Two paces: sparse (a frame
 * every {@value #SPARSE_GAP_MILLIS} ms, near the thesis scenario's 14 frames/s and slower than the event log's 50 ms
 * write delay) and flat out. Prints figures (median and 90th percentile per record; the floor beside them, not
 * subtracted), asserts nothing.
 * Run with the distribution's JIT options for comparable figures:
 * {@code java -XX:TieredStopAtLevel=1 -cp <test-classes>:<classes>:<cp> org.tinysep.runtime.internal.log.PacketRecordCost}
 */
public final class PacketRecordCost {

    static final int SPARSE_GAP_MILLIS = 60;
    private static final byte[] MOTION = {4, (byte) 161, 17, 0, 1, 1, (byte) 244, 4, 100, 5, 0, 1};
    private static final String ORIGIN = "node 1.17 via 127.0.0.1:44777";
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();

    /** The floor: a packet log that does nothing. */
    private static final class Empty implements PacketLog {
        volatile int calls;

        @Override
        public void record(Direction direction, String origin, byte[] bytes, String note) {
            calls++;
        }

        @Override
        public List<PacketEntry> recent(int max) {
            return List.of();
        }
    }

    private PacketRecordCost() {
    }

    public static void main(String[] args) throws Exception {
        int sparse = args.length > 0 ? Integer.parseInt(args[0]) : 300;
        Path root = Files.createTempDirectory("tinysep-record-cost");
        System.out.printf("packet record cost, Java %s, %d CPUs, load %.1f%n", System.getProperty("java.version"),
                Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        for (int round = 1; round <= 2; round++) { // round 1 warms the code up
            PacketLogService disk = packets(root.resolve("r" + round));
            Empty empty = new Empty();
            String floorSparse = sparse(empty, sparse);
            PacketLogService memory = new PacketLogService();
            memory.configure(() -> 20_000);
            String memorySparse = sparse(memory, sparse);
            long writer0 = writerCpu();
            String diskSparse = sparse(disk, sparse);
            String writerSparse = String.format("%.1f µs", (writerCpu() - writer0) / 1e3 / sparse);
            String floorFlat = flat(empty, 1_000_000);
            String diskFlat = flat(disk, 1_000_000);
            disk.deactivate();
            System.out.printf("round %d%n  sparse (1 per %d ms, %d records): floor %s | in memory only %s"
                    + " | packet log with its files %s; its writer thread %s per record%n"
                    + "  flat out (1,000,000 records): floor %s | packet log %s%n",
                    round, SPARSE_GAP_MILLIS, sparse, floorSparse, memorySparse, diskSparse, writerSparse, floorFlat,
                    diskFlat);
        }
        delete(root);
    }

    /** @return median and p90 of the recording thread's CPU time per call, one call every few milliseconds */
    private static String sparse(PacketLog log, int n) throws InterruptedException {
        long[] cost = new long[n];
        for (int i = 0; i < n; i++) {
            Thread.sleep(SPARSE_GAP_MILLIS);
            long t0 = CPU.getCurrentThreadCpuTime();
            log.record(Direction.RECEIVED, ORIGIN, MOTION, "");
            cost[i] = CPU.getCurrentThreadCpuTime() - t0;
        }
        Arrays.sort(cost);
        return String.format("p50 %.2f µs, p90 %.2f µs", cost[n / 2] / 1e3, cost[n * 9 / 10] / 1e3);
    }

    /** @return the CPU time of the packet log's writer thread so far, in ns */
    private static long writerCpu() {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals("tinysep-packets-writer")) {
                return CPU.getThreadCpuTime(t.getId());
            }
        }
        return 0;
    }

    /** @return the recording thread's CPU time per call, calls back to back */
    private static String flat(PacketLog log, int n) {
        long t0 = CPU.getCurrentThreadCpuTime();
        for (int i = 0; i < n; i++) {
            log.record(Direction.RECEIVED, ORIGIN, MOTION, "");
        }
        return String.format("%.3f µs per record", (CPU.getCurrentThreadCpuTime() - t0) / 1e3 / n);
    }

    private static PacketLogService packets(Path dir) {
        PacketLogService log = new PacketLogService();
        log.configure(() -> 20_000);
        log.persist(new LogSettings(dir, 64L * 1024 * 1024, 64, Duration.ZERO, Duration.ofSeconds(2)));
        return log;
    }

    private static void delete(Path root) throws IOException {
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}
