package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Comparator;
import java.util.stream.Stream;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.LogQuery;

/**
 * Prints how fast the log history is written, what a stored entry costs on disk, how long {@code record} takes on
 * the caller's thread and how long a query over the files takes. Prints figures, asserts nothing. Run:
 * {@code java -cp <test-classes>:<classes>:<api>:<slf4j-api> org.tinysep.runtime.internal.log.LogWriterBenchmark [dir]}
 * (see docs/logs.md).
 */
public final class LogWriterBenchmark {

    private static final byte[] MOTION = {4, (byte) 161, 17, 0, 1, 1, (byte) 244, 4, 100, 5, 0, 1};
    private static final String ORIGIN = "node 1.17 via 127.0.0.1:44777";

    private LogWriterBenchmark() {
    }

    public static void main(String[] args) throws IOException {
        Path root = args.length > 0 ? Path.of(args[0]) : Files.createTempDirectory("tinysep-log-bench");
        System.out.printf("log benchmark in %s, Java %s, %d CPUs%n", root, System.getProperty("java.version"),
                Runtime.getRuntime().availableProcessors());
        burst(root.resolve("burst"), 2_000_000);
        for (int rate : new int[] {10_000, 50_000, 100_000, 200_000}) {
            paced(root.resolve("paced-" + rate), rate, Duration.ofSeconds(3));
        }
        events(root.resolve("events"), 500_000);
        if (args.length == 0) {
            delete(root);
        }
    }

    /** The producer appends as fast as it can: the writer's best rate and how much a ring of 20 000 loses. */
    private static void burst(Path dir, int n) {
        PacketLogService log = packets(dir);
        long t0 = System.nanoTime();
        for (int i = 0; i < n; i++) {
            log.record(Direction.RECEIVED, ORIGIN, MOTION, "");
        }
        long t1 = System.nanoTime();
        log.persistent().flush();
        long t2 = System.nanoTime();
        PersistentLog<?> p = log.persistent();
        long written = n - p.skipped();
        System.out.printf("packets burst: %,d records in %.0f ms (%.0f ns per record on the caller's thread); "
                + "writer %,d written = %,.0f entries/s, %,d overwritten in the ring before written; "
                + "%.1f bytes per entry%n", n, ms(t1 - t0), (t1 - t0) / (double) n, written,
                written / ((t2 - t0) / 1e9), p.skipped(), p.bytesWritten() / (double) written);
        for (int round = 1; round <= 3; round++) {
            long q0 = System.nanoTime();
            long matched = log.query(new LogQuery(null, null, java.util.Set.of("node 1.17"),
                    java.util.Set.of("RECEIVED"), 20)).matched();
            long q1 = System.nanoTime();
            System.out.printf("packets query %d over %s: %,d matched in %.0f ms%n", round, size(dir), matched,
                    ms(q1 - q0));
        }
        log.deactivate();
    }

    /** The producer appends at a fixed rate: does the writer keep up (nothing overwritten)? */
    private static void paced(Path dir, int rate, Duration duration) {
        PacketLogService log = packets(dir);
        long n = rate * duration.toSeconds();
        long start = System.nanoTime();
        for (long i = 0; i < n; i++) {
            long due = start + i * 1_000_000_000L / rate;
            while (System.nanoTime() < due) {
                Thread.onSpinWait();
            }
            log.record(Direction.RECEIVED, ORIGIN, MOTION, "");
        }
        log.persistent().flush();
        System.out.printf("packets at %,d/s for %d s: %,d recorded, %,d overwritten before written%n", rate,
                duration.toSeconds(), n, log.persistent().skipped());
        log.deactivate();
    }

    private static void events(Path dir, int n) {
        EventLogService log = new EventLogService();
        log.start(() -> 10_000, r -> { }, e -> { }); // no SLF4J echo: only the file writer
        log.persist(LogSettings.in(dir));
        long t0 = System.nanoTime();
        for (int i = 0; i < n; i++) {
            log.record(EventKind.DEVICE_EVENT, "e531abe3-6136-338e-b202-89c1a0e04197",
                    i % 2 == 0 ? "movement detected" : "no movement");
        }
        long t1 = System.nanoTime();
        log.persistent().flush();
        long t2 = System.nanoTime();
        PersistentLog<?> p = log.persistent();
        long written = n - p.skipped();
        System.out.printf("events burst: %,d records (%.0f ns each); writer %,.0f entries/s, %,d overwritten; "
                + "%.1f bytes per entry%n", n, (t1 - t0) / (double) n, written / ((t2 - t0) / 1e9), p.skipped(),
                p.bytesWritten() / (double) written);
        log.persist(null);
    }

    private static PacketLogService packets(Path dir) {
        PacketLogService log = new PacketLogService();
        log.configure(() -> 20_000);
        log.persist(new LogSettings(dir, 64L * 1024 * 1024, 64, Duration.ZERO, Duration.ofSeconds(2)));
        return log;
    }

    private static double ms(long nanos) {
        return nanos / 1e6;
    }

    private static String size(Path dir) {
        try (Stream<Path> s = Files.list(dir)) {
            long bytes = s.mapToLong(f -> f.toFile().length()).sum();
            return String.format("%.1f MB", bytes / 1e6);
        } catch (IOException e) {
            return "?";
        }
    }

    private static void delete(Path root) throws IOException {
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}
