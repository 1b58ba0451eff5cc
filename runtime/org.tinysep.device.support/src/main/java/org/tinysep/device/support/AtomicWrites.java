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
 * Crash-safe file replacement: temp file in the same folder, write, {@code FileChannel.force}, atomic rename over
 * the target, fsync of the folder. A reader sees the old content or the new one, never a mix.
 */
public final class AtomicWrites {

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")
            .withZone(ZoneOffset.UTC);

    private AtomicWrites() {
    }

    /** Replaces {@code target} with {@code bytes} atomically (creates the folder when needed). */
    public static void write(Path target, byte[] bytes) throws IOException {
        write(target, bytes, () -> { });
    }

    /**
     * Replaces {@code target} with {@code bytes} atomically.
     *
     * @param beforeRename test seam: runs after the temp file is written and synced, before the rename
     */
    public static void write(Path target, byte[] bytes, Runnable beforeRename) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        Path tmp = Files.createTempFile(dir, target.getFileName() + ".", ".tmp");
        try {
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
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

    private static void syncDirectory(Path dir) {
        try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
            ch.force(true);
        } catch (IOException | UnsupportedOperationException ignored) {
            // not every platform can sync a directory; the rename itself is atomic
        }
    }
}
