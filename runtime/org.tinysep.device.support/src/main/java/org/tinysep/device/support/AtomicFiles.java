package org.tinysep.device.support;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;

/**
 * Crash-safe file replacement, shared by everything that keeps state on disk (House Information, the backup
 * store, the drivers list): a temp file in the same folder is written and forced to disk, atomically renamed over the target, and
 * the folder is synced, so after a crash the target holds either the old or the new content, never a mix.
 */
public final class AtomicFiles {

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")
            .withZone(ZoneOffset.UTC);

    private AtomicFiles() {
    }

    /** Writes {@code bytes} to {@code target} atomically (creating its folder). */
    public static void write(Path target, byte[] bytes) throws IOException {
        write(target, bytes, () -> { });
    }

    /**
     * As {@link #write(Path, byte[])}; {@code beforeRename} runs after the temp file is synced and before it
     * replaces the target (a test seam for crash simulations).
     */
    public static void write(Path target, byte[] bytes, Runnable beforeRename) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        Path tmp = Files.createTempFile(dir, target.getFileName() + ".", ".tmp");
        try {
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING)) {
                ByteBuffer buf = ByteBuffer.wrap(bytes);
                while (buf.hasRemaining()) {
                    ch.write(buf);
                }
                ch.force(true);
            }
            beforeRename.run();
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(tmp);
        }
        syncDirectory(dir);
    }

    /** Moves {@code from} to {@code to} atomically (same file system) and syncs both folders. */
    public static void move(Path from, Path to) throws IOException {
        Files.createDirectories(to.toAbsolutePath().getParent());
        Files.move(from, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        syncDirectory(to.toAbsolutePath().getParent());
        syncDirectory(from.toAbsolutePath().getParent());
    }

    /**
     * Moves a damaged {@code file} aside to {@code <name>.broken-<yyyyMMdd-HHmmss>} (UTC; {@code -2}, {@code -3} … when
     * taken) so that it is kept for inspection and never read again.
     *
     * @return the new path
     */
    public static Path moveAside(Path file, Instant now) throws IOException {
        String base = file.getFileName() + ".broken-" + STAMP.format(now);
        Path aside = file.resolveSibling(base);
        for (int i = 2; Files.exists(aside); i++) {
            aside = file.resolveSibling(base + "-" + i);
        }
        Files.move(file, aside, StandardCopyOption.ATOMIC_MOVE);
        syncDirectory(file.toAbsolutePath().getParent());
        return aside;
    }

    /** Deletes {@code file} if present and syncs its folder. */
    public static void delete(Path file) throws IOException {
        if (Files.deleteIfExists(file)) {
            syncDirectory(file.toAbsolutePath().getParent());
        }
    }

    /** Forces a folder's entries (a rename or delete) to disk; a no-op where the platform cannot. */
    public static void syncDirectory(Path dir) {
        try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
            ch.force(true);
        } catch (IOException | UnsupportedOperationException ignored) {
            // not every platform can sync a directory; the rename itself is atomic
        }
    }
}
