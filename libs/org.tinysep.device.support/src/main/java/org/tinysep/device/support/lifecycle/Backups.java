package org.tinysep.device.support.lifecycle;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.log.EventKind;

/**
 * A driver's way to the device manager's {@link BackupStore} (thesis 3.7), when one is installed; without it,
 * nothing is saved or restored. Never throws: a store that fails is logged.
 */
public final class Backups implements AutoCloseable {

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

    /**
     * Over the store {@code store} supplies (null: none now), e.g. a driver context's platform services.
     */
    static Backups over(Supplier<BackupStore> store) {
        return new Backups(store, () -> { });
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

    /**
     * Re-creates devices from their backups (a bus radio's known nodes, before its hardware opens): each backup is
     * turned into a device, claimed (e.g. put into the node table unless the node is already there) and
     * registered; a backup that cannot be used is reported in the event log and skipped.
     *
     * @return how many devices were re-created
     */
    public static <D> int recreate(DriverContext context, List<ComponentBackup> saved,
            Function<ComponentBackup, D> make, Predicate<D> claim, UnaryOperator<D> register) {
        int n = 0;
        for (ComponentBackup b : saved) {
            try {
                D device = make.apply(b);
                if (claim.test(device)) {
                    register.apply(device);
                    n++;
                }
            } catch (RuntimeException e) {
                context.event(EventKind.PROBLEM, "cannot re-create node " + b.nodeAddress() + " (" + b.uid()
                        + ") from its backup: " + e.getMessage());
            }
        }
        return n;
    }

    @Override
    public void close() {
        onClose.run();
    }
}
