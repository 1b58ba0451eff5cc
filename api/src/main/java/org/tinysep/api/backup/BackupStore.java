package org.tinysep.api.backup;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletionStage;
import org.osgi.annotation.versioning.ProviderType;

/**
 * The device manager's backup store (thesis 3.7): one XML file per driver and device, written atomically, read
 * back when the platform starts. Owners save whenever their settings change; saving never does disk I/O on the
 * caller's thread, and several saves of one component before it is written are coalesced into one write.
 */
@ProviderType
public interface BackupStore {

    /**
     * Queues the backup for writing, replacing an older one of the same UID.
     *
     * @return completes once this backup (or a newer one of the component) is on disk, exceptionally when it
     *         could not be written
     */
    CompletionStage<Void> save(ComponentBackup backup);

    /**
     * Waits until every backup saved before this call is on disk; what acknowledges a change to a user (the
     * shell's {@code set}) calls it, so an acknowledged change survives a crash.
     *
     * @return whether it is all on disk within the timeout
     */
    boolean flush(Duration timeout);

    /** @return the newest backup of that component (saved or read from disk), if any */
    Optional<ComponentBackup> find(String uid);

    /** @return the backups of a driver's devices (kind {@link ComponentKind#DEVICE}), oldest first */
    List<ComponentBackup> devicesOf(String driverUid);

    /** Forgets a component for good (its file is deleted): the user removed it. */
    void delete(String uid);
}
