package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.device.support.files.StateFolder;

/**
 * The device manager's backup store (thesis 3.7): on activation reads every backup file (damaged ones are moved
 * aside and reported in the event log, the rest load), maps each to its component by UID, and gives drivers their
 * devices' backups. Saves are written by its own thread ({@link BackupWriter}).
 */
@Component(service = {BackupStore.class, BackupStoreService.class}, immediate = true,
        configurationPid = BackupStoreService.PID)
@Designate(ocd = BackupConfig.class)
public final class BackupStoreService implements BackupStore {

    public static final String PID = "org.tinysep.runtime.backup";
    static final String ORIGIN = "BackupStore";
    private static final Logger LOG = LoggerFactory.getLogger(BackupStoreService.class);

    private final Map<String, ComponentBackup> backups = new ConcurrentHashMap<>();
    private final Map<String, Path> written = new ConcurrentHashMap<>();
    private final EventLog events;
    private final BackupFiles files;
    private final ScheduledExecutorService executor;
    private final BackupWriter writer;
    /** Last seen times an orderly stop saves in one file instead of a backup file per device. */
    private final LastSeenJournal journal;
    private volatile ArchiveUnpacker.Limits limits = DEFAULT_LIMITS;
    private long stopSaveMillis = 25_000;
    static final ArchiveUnpacker.Limits DEFAULT_LIMITS = new ArchiveUnpacker.Limits(64L << 20, 8L << 20, 10_000);

    @Activate
    public BackupStoreService(BundleContext context, BackupConfig config,
            @Reference(name = "eventLog") EventLog events) {
        this(StateFolder.resolveOrDataArea(config.folder(), context, "backup"), Math.max(0, config.writeDelayMillis()), events);
        this.stopSaveMillis = Math.max(1, config.stopSaveSeconds()) * 1000L;
        this.limits = new ArchiveUnpacker.Limits(positive(config.restoreMaxBytes(), DEFAULT_LIMITS.maxTotalBytes()),
                positive(config.restoreMaxFileBytes(), DEFAULT_LIMITS.maxEntryBytes()),
                (int) positive(config.restoreMaxFiles(), DEFAULT_LIMITS.maxEntries()));
        // the framework is stopping: write the backlog now, while the drivers stop (10,000 devices take a while),
        // not after them; a synchronous listener is told before any bundle stops
        this.frameworkStopping = e -> {
            if (e.getType() == org.osgi.framework.BundleEvent.STOPPING && e.getBundle().getBundleId() == 0) {
                frameworkStopping();
            }
        };
        context.addBundleListener(frameworkStopping);
        this.context = context;
    }

    private org.osgi.framework.SynchronousBundleListener frameworkStopping;
    /** System.nanoTime() when the framework began to stop; 0 before. */
    private volatile long stoppingSince;
    private BundleContext context;

    private static long positive(long value, long otherwise) {
        if (value > 0) {
            return value;
        }
        LOG.warn("Backup store: a restore limit of {} is not positive; using {}", value, otherwise);
        return otherwise;
    }

    /** @return the bounds on what {@code tinysep:restore} reads (config keys restoreMax*) */
    ArchiveUnpacker.Limits limits() {
        return limits;
    }

    BackupStoreService(Path root, long writeDelayMillis, EventLog events) {
        this.events = events;
        this.files = new BackupFiles(new BackupLayout(root), new BackupCodec());
        java.util.concurrent.ScheduledThreadPoolExecutor ex = new java.util.concurrent.ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "tinysep-backup-writer");
            t.setDaemon(true);
            return t;
        });
        ex.setExecuteExistingDelayedTasksAfterShutdownPolicy(false); // the stop writes at once instead
        this.executor = ex;
        this.writer = new BackupWriter(files, written, executor, writeDelayMillis, this::writeFailed);
        this.journal = new LastSeenJournal(files.layout().root());
        load();
    }

    /**
     * The framework begins to stop (before any bundle stops): the backlog is written at once, and for refreshes of
     * backups already on disk (a device's last state as it stops) the stop's time limit ({@code stopSaveSeconds})
     * counts from now, the drivers' own stop included (10,000 devices take 38-60 s to stop, which a limit counted
     * only from this store's own deactivation would not cover). Backups with no file yet (devices just created) go
     * first and keep the limit from the store's deactivation: a device is never lost to a slow stop, a refresh may be.
     */
    void frameworkStopping() {
        long now = System.nanoTime();
        stoppingSince = now == 0 ? 1 : now;
        writer.stopBy(stoppingSince + TimeUnit.MILLISECONDS.toNanos(stopSaveMillis), 0);
        writer.flush();
    }

    /** Reads the folder again (after {@code tinysep:restore} replaced it); unsaved changes are written first. */
    public synchronized void reload() {
        writer.drain();
        backups.clear();
        written.clear();
        try {
            journal.discard(); // the restored folder says when each node was last seen
        } catch (IOException e) {
            LOG.warn("Backup store: cannot delete {}: {}", LastSeenJournal.FILE, e.toString());
        }
        load();
    }

    private void load() {
        try {
            List<BackupFiles.Loaded> loaded = files.loadAll(Instant.now(), this::damaged);
            for (BackupFiles.Loaded l : loaded) {
                ComponentBackup old = backups.get(l.backup().uid());
                if (old == null || l.backup().savedAt().isAfter(old.savedAt())) {
                    backups.put(l.backup().uid(), l.backup());
                    written.put(l.backup().uid(), l.file());
                }
            }
            LOG.info("Backup store {}: {} component backup(s)", files.layout().root(), backups.size());
        } catch (IOException | RuntimeException e) {
            LOG.error("Cannot read the backup folder {}: {}", files.layout().root(), e.toString());
            events.record(EventKind.PROBLEM, ORIGIN, "cannot read the backup folder " + files.layout().root()
                    + ": " + e.getMessage() + "; starting without backups");
        }
        try {
            applyJournal();
        } catch (IOException | RuntimeException e) {
            damaged(root().resolve(LastSeenJournal.FILE), "unreadable: " + e.getMessage()
                    + "; the backups keep the last seen times of their files");
        }
    }

    /** Applies the last seen times the last orderly stop saved to the backups whose file is older. */
    private void applyJournal() throws IOException {
        journal.read(problem -> damaged(root().resolve(LastSeenJournal.FILE), problem)).forEach((uid, at) -> {
            ComponentBackup b = backups.get(uid);
            if (b == null || (b.lastSeen() != null && !at.isAfter(b.lastSeen()))) {
                journal.forget(uid); // gone, or its file is as new
            } else {
                backups.put(uid, LastSeenJournal.withLastSeen(b, at, b.savedAt()));
            }
        });
    }

    /**
     * An orderly stop saves every backup still queued (a burst of new devices can leave the writer thousands behind):
     * at once, without the write delay, on this thread after the writer's current batch; said in the log and the
     * event log with the count, bounded by {@code stopSaveSeconds} from the start of the framework's stop (a disk
     * that hangs must not hang the stop), never-saved backups first.
     */
    @Deactivate
    void deactivate() throws InterruptedException {
        if (context != null) {
            try {
                context.removeBundleListener(frameworkStopping);
            } catch (IllegalStateException stopped) {
                // the bundle is already stopping
            }
        }
        saveJournal();
        int backlog = writer.backlog();
        long t0 = System.nanoTime();
        if (backlog > 0) {
            say(String.format("saving %,d device backup(s) before stopping…", backlog));
        }
        long since = stoppingSince;
        long limit = TimeUnit.MILLISECONDS.toNanos(stopSaveMillis);
        writer.stopBy((since != 0 ? since : t0) + limit, t0 + limit);
        executor.shutdown(); // the delayed run is dropped (policy set at construction): this thread writes now
        writer.drain(); // after the writer thread's current batch, which also keeps to the limit
        int stale = writer.notRefreshed();
        if (stale > 0) {
            say(String.format("the last state of %,d device(s) was not saved within %d s of the stop"
                    + " (stopSaveSeconds): their previous backups stay", stale, stopSaveMillis / 1000));
        }
        int left = writer.notSaved();
        if (left > 0) {
            String msg = String.format("stopping with %,d device backup(s) not saved: the disk took longer than"
                    + " %d s (stopSaveSeconds); those devices are created again when their nodes next report",
                    left, stopSaveMillis / 1000);
            LOG.error("Backup store: {}", msg);
            events.record(EventKind.PROBLEM, ORIGIN, msg);
        } else if (backlog > 0 && stale == 0) {
            say(String.format("saved %,d device backup(s) in %.1f s before stopping", backlog,
                    (System.nanoTime() - t0) / 1e9));
        }
        executor.awaitTermination(1, TimeUnit.SECONDS);
    }

    /** Writes the last seen times kept in the journal (one file); a failure is reported, never thrown. */
    private void saveJournal() {
        int n = journal.size();
        try {
            journal.write();
            if (n > 0) {
                LOG.info("Backup store: saved the last seen times of {} device(s) in {}", n, LastSeenJournal.FILE);
            }
        } catch (IOException | RuntimeException e) {
            String msg = String.format("cannot save the last seen times of %,d device(s) in %s: %s; their backups"
                    + " keep the times saved before", n, LastSeenJournal.FILE, e.getMessage());
            LOG.error("Backup store: {}", msg);
            events.record(EventKind.PROBLEM, ORIGIN, msg);
        }
    }

    /**
     * Writes the backup file of every device whose newest last seen time is only in {@link LastSeenJournal} (a backup
     * archive holds the files): before an archive is made or a restore takes its undo copy; then {@link #flush}.
     */
    void settleJournal() {
        for (String uid : journal.uids()) {
            journal.forget(uid);
            ComponentBackup b = backups.get(uid);
            if (b != null) {
                writer.write(b);
            }
        }
    }

    /** The stop's limit ({@code stopSaveSeconds}), in ms (tests). */
    void stopSaveMillisForTest(long millis) {
        stopSaveMillis = millis;
    }

    private void say(String message) {
        LOG.info("Backup store: {}", message);
        events.record(EventKind.STATUS, ORIGIN, message);
    }

    /** @return folder syncs of the writer so far (a burst of saves syncs each folder once, not once per file) */
    long foldersSynced() {
        return writer.foldersSynced();
    }

    /** @return the codec of the backup files (shared: a JAXB context is costly) */
    BackupCodec codec() {
        return files.codec();
    }

    /** @return the backup folder */
    public Path root() {
        return files.layout().root();
    }

    @Override
    public CompletionStage<Void> save(ComponentBackup backup) {
        ComponentBackup before = backups.put(backup.uid(), backup);
        if (stoppingSince != 0 && before != null && LastSeenJournal.fits(backup.uid())
                && LastSeenJournal.onlyLastSeenMoved(before, backup)) {
            // the framework stops and only the last seen time moved: one line in the journal, not a file
            journal.note(backup.uid(), backup.lastSeen());
            return CompletableFuture.completedFuture(null);
        }
        journal.forget(backup.uid()); // its file, written now, holds the newest
        return writer.write(backup);
    }

    @Override
    public boolean flush(Duration timeout) {
        CompletableFuture<Void> marker = writer.flush();
        try {
            marker.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
            return true;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        } catch (Exception e) {
            return false;
        }
    }

    @Override
    public Optional<ComponentBackup> find(String uid) {
        return Optional.ofNullable(backups.get(uid));
    }

    @Override
    public List<ComponentBackup> devicesOf(String driverUid) {
        return backups.values().stream()
                .filter(b -> b.kind() == ComponentKind.DEVICE && b.driverUid().equals(driverUid))
                .sorted(Comparator.comparing(ComponentBackup::uid)).toList();
    }

    /** @return every backup, by UID */
    public List<ComponentBackup> all() {
        return backups.values().stream().sorted(Comparator.comparing(ComponentBackup::uid)).toList();
    }

    @Override
    public void delete(String uid) {
        journal.forget(uid);
        if (backups.remove(uid) != null) {
            writer.delete(uid);
        }
    }

    private void damaged(Path file, String problem) {
        LOG.warn("Damaged backup file {}: {}", file, problem);
        events.record(EventKind.PROBLEM, ORIGIN, "damaged backup file " + file.getFileName() + ": " + problem);
    }

    private void writeFailed(String uid, String problem) {
        LOG.error("Cannot write the backup of {}: {}", uid, problem);
        events.record(EventKind.PROBLEM, ORIGIN, "cannot write the backup of " + uid + ": " + problem);
    }
}
