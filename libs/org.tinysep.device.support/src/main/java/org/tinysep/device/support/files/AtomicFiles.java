package org.tinysep.device.support.files;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileAttribute;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.Set;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;

/**
 * Crash-safe file replacement, shared by everything that keeps state on disk (House Information, the backup
 * store, the drivers list): a temp file in the same folder is written and forced to disk, atomically renamed over the target, and
 * the folder is synced, so after a crash the target holds either the old or the new content, never a mix.
 * <p>
 * State is private (docs/backup.md): on POSIX file systems the files it writes are {@code rw-------} (the temp file
 * is created so and keeps its mode through the rename) and the folders it creates {@code rwx------}; the logs and
 * the mail spool create their files with {@link #createPrivateFile}.
 */
public final class AtomicFiles {

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")
            .withZone(ZoneOffset.UTC);

    private AtomicFiles() {
    }

    /** POSIX mode of the state files TinySEP writes: only the owner may read them. */
    public static final Set<PosixFilePermission> PRIVATE_FILE = PosixFilePermissions.fromString("rw-------");
    /** POSIX mode of the state folders TinySEP creates. */
    public static final Set<PosixFilePermission> PRIVATE_FOLDER = PosixFilePermissions.fromString("rwx------");

    /** Creates {@code dir} and its missing parents as {@code rwx------} (on POSIX); existing folders are left alone. */
    public static Path createPrivateDirectories(Path dir) throws IOException {
        Path abs = dir.toAbsolutePath();
        if (Files.isDirectory(abs)) {
            return abs;
        }
        if (abs.getParent() != null) {
            createPrivateDirectories(abs.getParent());
        }
        try {
            return Files.createDirectories(abs, posix() ? new FileAttribute<?>[] {
                PosixFilePermissions.asFileAttribute(PRIVATE_FOLDER)} : new FileAttribute<?>[0]);
        } catch (java.nio.file.FileAlreadyExistsException raced) {
            return abs;
        }
    }

    /** Creates {@code file} empty as {@code rw-------} (on POSIX) unless it exists; @return the file */
    public static Path createPrivateFile(Path file) throws IOException {
        createPrivateDirectories(file.toAbsolutePath().getParent());
        try {
            return Files.createFile(file, posix() ? new FileAttribute<?>[] {
                PosixFilePermissions.asFileAttribute(PRIVATE_FILE)} : new FileAttribute<?>[0]);
        } catch (java.nio.file.FileAlreadyExistsException exists) {
            return file;
        }
    }

    private static boolean posix() {
        return java.nio.file.FileSystems.getDefault().supportedFileAttributeViews().contains("posix");
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
        replace(target, bytes, beforeRename);
        syncDirectory(target.toAbsolutePath().getParent());
    }

    /** The write without the folder sync (the caller syncs: {@link AtomicBatch}). */
    static void replace(Path target, byte[] bytes, Runnable beforeRename) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        createPrivateDirectories(dir);
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
    }

    /** Moves {@code from} to {@code to} atomically (same file system) and syncs both folders. */
    public static void move(Path from, Path to) throws IOException {
        createPrivateDirectories(to.toAbsolutePath().getParent());
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
