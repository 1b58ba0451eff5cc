package org.tinysep.device.support.lifecycle;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.backup.ComponentBackup;

/**
 * A backup store for the save-counting tests: keeps every save in order (each one a JAXB write and part of an fsync
 * batch in the real store), finds a device's latest, and fails its saves while {@link #failing} is set.
 */
final class CountingStore implements BackupStore {

    final List<ComponentBackup> saved = new ArrayList<>();
    volatile boolean failing;

    @Override
    public CompletionStage<Void> save(ComponentBackup backup) {
        saved.add(backup);
        return failing ? CompletableFuture.failedFuture(new IllegalStateException("disk full"))
                : CompletableFuture.completedFuture(null);
    }

    @Override
    public boolean flush(Duration timeout) {
        return true;
    }

    @Override
    public Optional<ComponentBackup> find(String uid) {
        return saved.stream().filter(b -> b.uid().equals(uid)).reduce((a, b) -> b);
    }

    @Override
    public List<ComponentBackup> devicesOf(String driverUid) {
        return List.of();
    }

    @Override
    public void delete(String uid) {
    }
}
