package org.tinysep.device.support;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.backup.ComponentBackup;

/**
 * A driver's way to the device manager's {@link BackupStore} (thesis 3.7), when one is installed; without it,
 * nothing is saved or restored. Never throws: a store that fails is logged.
 */
public final class Backups implements AutoCloseable {

    /** How long a user's change waits for its backup to reach the disk. */
    public static final Duration DURABLE_WAIT = Duration.ofSeconds(5);
    private static final Logger LOG = LoggerFactory.getLogger(Backups.class);

    private final Supplier<BackupStore> store;
    private final Runnable onClose;

    private Backups(Supplier<BackupStore> store, Runnable onClose) {
        this.store = store;
        this.onClose = onClose;
    }

    /** No backup store (unit tests, tools). */
    public static Backups none() {
        return new Backups(() -> null, () -> { });
    }

    /** Over one given store (unit tests). */
    public static Backups of(BackupStore store) {
        return new Backups(() -> store, () -> { });
    }

    /** Follows the BackupStore service as it comes and goes. */
    public static Backups tracking(BundleContext context) {
        ServiceTracker<BackupStore, BackupStore> t = new ServiceTracker<>(context, BackupStore.class, null);
        t.open();
        return new Backups(t::getService, t::close);
    }

    /** @return whether a store is there */
    public boolean available() {
        return store.get() != null;
    }

    /** Queues a backup; returns at once. */
    public CompletionStage<Void> save(ComponentBackup backup) {
        BackupStore s = store.get();
        if (s == null) {
            return CompletableFuture.completedFuture(null);
        }
        try {
            return s.save(backup);
        } catch (RuntimeException e) {
            LOG.warn("Backup store refused the backup of {}: {}", backup.uid(), e.toString());
            return CompletableFuture.failedFuture(e);
        }
    }

    /**
     * Saves and waits until the backup is on disk (at most {@link #DURABLE_WAIT}).
     *
     * @return null when it is on disk (or there is no store), else why not
     */
    public String saveDurably(ComponentBackup backup) {
        try {
            save(backup).toCompletableFuture().get(DURABLE_WAIT.toMillis(), TimeUnit.MILLISECONDS);
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        } catch (Exception e) {
            return e.getCause() == null ? e.toString() : e.getCause().toString();
        }
    }

    /** @return the component's backup, if there is one */
    public Optional<ComponentBackup> find(String uid) {
        BackupStore s = store.get();
        try {
            return s == null ? Optional.empty() : s.find(uid);
        } catch (RuntimeException e) {
            LOG.warn("Backup store failed to find {}: {}", uid, e.toString());
            return Optional.empty();
        }
    }

    /** @return the backups of a driver's devices */
    public List<ComponentBackup> devicesOf(String driverUid) {
        BackupStore s = store.get();
        try {
            return s == null ? List.of() : s.devicesOf(driverUid);
        } catch (RuntimeException e) {
            LOG.warn("Backup store failed to list the devices of {}: {}", driverUid, e.toString());
            return List.of();
        }
    }

    /** Forgets a component for good. */
    public void delete(String uid) {
        BackupStore s = store.get();
        if (s != null) {
            try {
                s.delete(uid);
            } catch (RuntimeException e) {
                LOG.warn("Backup store failed to delete {}: {}", uid, e.toString());
            }
        }
    }

    @Override
    public void close() {
        onClose.run();
    }
}
