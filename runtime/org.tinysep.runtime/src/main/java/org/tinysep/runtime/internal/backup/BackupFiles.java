package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.stream.Stream;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.files.AtomicBatch;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The backup files on disk: reads them all (a damaged one is moved aside and reported, the others still load),
 * writes and deletes one atomically. Not thread-safe: the store calls it from its writer thread, or before it is
 * published.
 */
final class BackupFiles {

    /** What loading found: the good backups and where each lives. */
    record Loaded(ComponentBackup backup, Path file) {
    }

    private final BackupLayout layout;
    private final BackupCodec codec;

    BackupFiles(BackupLayout layout, BackupCodec codec) {
        this.layout = layout;
        this.codec = codec;
    }

    BackupLayout layout() {
        return layout;
    }

    BackupCodec codec() {
        return codec;
    }

    /**
     * Reads every {@code *.xml} below the root (except {@code damaged/}); leftover temp files of an interrupted
     * write are deleted.
     *
     * @param damaged told the file and the reason for each file moved aside
     */
    List<Loaded> loadAll(Instant now, BiConsumer<Path, String> damaged) throws IOException {
        List<Loaded> out = new ArrayList<>();
        Path root = layout.root();
        if (!Files.isDirectory(root)) {
            return out;
        }
        List<Path> files;
        try (Stream<Path> walk = Files.walk(root, 2)) {
            files = walk.filter(Files::isRegularFile)
                    .filter(p -> !p.getParent().equals(layout.damagedFolder())).sorted().toList();
        }
        for (Path f : files) {
            String n = f.getFileName().toString();
            if (n.endsWith(".tmp")) {
                Files.deleteIfExists(f); // a write interrupted before its rename: the old file is intact
            } else if (n.endsWith(BackupLayout.SUFFIX)) {
                load(f, now, damaged, out);
            }
        }
        return out;
    }

    private void load(Path f, Instant now, BiConsumer<Path, String> damaged, List<Loaded> out) throws IOException {
        String problem;
        try {
            ComponentBackup b = codec.read(Files.readAllBytes(f));
            out.add(new Loaded(b, f));
            return;
        } catch (BadBackupException e) {
            problem = e.getMessage();
        } catch (IOException e) {
            problem = "unreadable: " + e.getMessage();
        }
        Path aside = layout.damagedName(f, now);
        AtomicFiles.move(f, aside);
        damaged.accept(f, problem + "; moved aside to " + layout.root().relativize(aside));
    }

    /** Writes the backup to its file, durable at the batch's commit; returns that file. */
    Path write(ComponentBackup b, AtomicBatch batch) throws IOException {
        Path file = layout.fileOf(b);
        batch.write(file, codec.write(b));
        return file;
    }
}
