package org.tinysep.runtime.internal.health;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/**
 * One check of the state folder's disk (disk-full handling). Below the minimum free space, the
 * log history goes first: the oldest packet-log files, then the oldest event-log files, never the file each log is
 * writing, until the minimum is free again. Then one {@code PROBLEM} in plain words per episode (how much is free,
 * what was deleted, what to do); a {@code STATUS} when there is room again. State files are not touched: they are
 * written atomically ({@code AtomicFiles}), so a full disk makes a save fail and leaves the old file as it was.
 */
final class DiskCheck {

    static final String ORIGIN = "disk";
    private static final Logger LOG = LoggerFactory.getLogger(DiskCheck.class);
    private static final long MB = 1024 * 1024;

    private final Path var;
    private final Path logs;
    private volatile long minFreeBytes;
    private final EventLog eventLog;
    private boolean low;

    DiskCheck(Path var, Path logs, long minFreeMegabytes, EventLog eventLog) {
        this.var = var;
        this.logs = logs;
        this.minFreeBytes = minFreeMegabytes * MB;
        this.eventLog = eventLog;
    }

    /** Sets the minimum free space (a changed configuration). */
    void minimum(long minFreeMegabytes) {
        minFreeBytes = minFreeMegabytes * MB;
    }

    /** @return whether the disk is below the minimum after the check (and the trimming) */
    synchronized boolean check() {
        long free = free();
        if (minFreeBytes <= 0 || free < 0 || free >= minFreeBytes) {
            if (low && free >= minFreeBytes) {
                low = false;
                eventLog.record(EventKind.STATUS, ORIGIN, String.format(Locale.ROOT, "the disk holding the state "
                        + "folder %s has room again: %s free", var, mb(free)));
            }
            return false;
        }
        int deleted = 0;
        long freed = 0;
        for (Path f : trimmable()) {
            try {
                long size = Files.size(f);
                Files.deleteIfExists(f);
                deleted++;
                freed += size;
                LOG.info("Disk nearly full: deleted the old log file {}", f.getFileName());
            } catch (IOException e) {
                LOG.warn("Disk nearly full: cannot delete {}: {}", f, e.toString());
            }
            free = free();
            if (free >= minFreeBytes) {
                break;
            }
        }
        boolean still = free < minFreeBytes;
        if (!low || deleted > 0) {
            String trimmed = deleted == 0 ? "there were no old log files left to delete"
                    : "deleted the " + deleted + " oldest log file" + (deleted == 1 ? "" : "s") + " (" + mb(freed)
                    + ") to make room" + (still ? ", and it is still too little" : "");
            eventLog.record(EventKind.PROBLEM, ORIGIN, String.format(Locale.ROOT, "the disk holding the state folder "
                    + "%s is nearly full: %s free, less than the %s TinySEP keeps free; %s. Free space on this "
                    + "disk soon: when it is full, settings, alerts and logs can no longer be saved (the files "
                    + "already saved stay intact)", var, mb(still ? free : free - freed), mb(minFreeBytes), trimmed));
        }
        low = still;
        return still;
    }

    /** @return old log files, the ones to delete first first: packets oldest first, then events oldest first */
    List<Path> trimmable() {
        List<Path> out = new ArrayList<>(olderFiles("packets"));
        out.addAll(olderFiles("events"));
        return out;
    }

    private List<Path> olderFiles(String prefix) {
        List<Path> files = new ArrayList<>();
        if (logs == null || !Files.isDirectory(logs)) {
            return files;
        }
        try (DirectoryStream<Path> dir = Files.newDirectoryStream(logs, prefix + "-*.log")) {
            dir.forEach(p -> {
                if (p.getFileName().toString().matches("\\Q" + prefix + "\\E-\\d{20}\\.log")) {
                    files.add(p);
                }
            });
        } catch (IOException e) {
            LOG.warn("Cannot list {}: {}", logs, e.toString());
        }
        files.sort(null);
        return files.isEmpty() ? files : files.subList(0, files.size() - 1); // never the file being written
    }

    private long free() {
        try {
            return Files.getFileStore(Files.isDirectory(var) ? var : var.getParent()).getUsableSpace();
        } catch (IOException | RuntimeException e) {
            LOG.warn("Cannot read the free space of {}: {}", var, e.toString());
            return -1;
        }
    }

    private static String mb(long bytes) {
        return String.format(Locale.ROOT, "%.1f MB", bytes / (double) MB);
    }
}
