package org.tinysep.runtime.internal.log;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.List;

/**
 * The log services' test seams for tests in other packages (the shell's log commands over real log files): a
 * service on a test clock, its history kept in a folder or in memory only, flushed to the files, and the files.
 */
public final class LogSeams {

    private LogSeams() {
    }

    /** @return an event log on {@code clock} with a ring of {@code capacity}, echoing nowhere */
    public static EventLogService events(Clock clock, int capacity) {
        EventLogService log = new EventLogService(clock);
        log.start(() -> capacity, Runnable::run, e -> { });
        return log;
    }

    /** @return a packet log on {@code clock} with a ring of {@code capacity} */
    public static PacketLogService packets(Clock clock, int capacity) {
        PacketLogService log = new PacketLogService(clock);
        log.configure(() -> capacity);
        return log;
    }

    /** Keeps the history in {@code folder} with the default settings (null folder: memory only). */
    public static void keepIn(EventLogService log, Path folder) {
        log.persist(folder == null ? null : LogSettings.in(folder));
    }

    /** Keeps the history in {@code folder} with the default settings (null folder: memory only). */
    public static void keepIn(PacketLogService log, Path folder) {
        log.persist(folder == null ? null : LogSettings.in(folder));
    }

    /** Keeps the history in {@code folder}: at most {@code maxFiles} of {@code maxFileBytes}, no retention. */
    public static void keepIn(PacketLogService log, Path folder, long maxFileBytes, int maxFiles, Duration sync) {
        log.persist(new LogSettings(folder, maxFileBytes, maxFiles, Duration.ZERO, sync));
    }

    /** Writes what the ring holds to the files and forces it to the disk. */
    public static void flush(EventLogService log) {
        log.persistent().flush();
    }

    /** Writes what the ring holds to the files and forces it to the disk. */
    public static void flush(PacketLogService log) {
        log.persistent().flush();
    }

    /** Deactivates the service: its files are written and closed. */
    public static void close(PacketLogService log) {
        log.deactivate();
    }

    /** @return the rotating files of the log {@code prefix} ({@code events}, {@code packets}), oldest first */
    public static List<Path> files(Path folder, String prefix) {
        return new LogFolder(folder, prefix).files();
    }
}
