package org.tinysep.device.support;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * Many crash-safe file replacements with one folder sync per folder (a group commit). Each {@link #write} is as
 * {@link AtomicFiles#write(Path, byte[])} (temp file, forced, atomically renamed: after a crash the file holds its
 * old or its new content) except that the folder is not synced at once; {@link #commit} syncs every folder touched,
 * once. Only after {@code commit} returns are the renames and deletes durable: acknowledge to callers then.
 * <p>
 * A burst of 1,000 device creations thus costs 1,000 file syncs but 2 folder syncs instead of 1,000 (issue 14).
 * Not thread-safe: one writer thread uses one batch.
 */
public final class AtomicBatch {

    private final Set<Path> folders = new LinkedHashSet<>();
    private long foldersSynced;

    /** Replaces {@code target} with {@code bytes} (creating its folder); durable after {@link #commit}. */
    public void write(Path target, byte[] bytes) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        AtomicFiles.replace(target, bytes, () -> { });
        folders.add(dir);
    }

    /** Deletes {@code file} if present; durable after {@link #commit}. */
    public void delete(Path file) throws IOException {
        if (Files.deleteIfExists(file)) {
            folders.add(file.toAbsolutePath().getParent());
        }
    }

    /** Syncs every folder written or deleted in since the last commit, once each. */
    public void commit() {
        for (Path dir : folders) {
            AtomicFiles.syncDirectory(dir);
            foldersSynced++;
        }
        folders.clear();
    }

    /** @return folder syncs made by this batch's commits so far (the cost a burst saves) */
    public long foldersSynced() {
        return foldersSynced;
    }
}
