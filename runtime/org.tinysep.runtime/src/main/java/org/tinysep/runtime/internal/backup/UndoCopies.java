package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The copies of the state a restore replaced, {@code ${tinysep.var}/before-restore/previous-<UTC time>.zip}: complete
 * (passwords and secrets included, for {@code tinysep:restore --undo}), signed, {@code rw-------}; the newest
 * {@value #COPIES_KEPT} are kept.
 */
final class UndoCopies {

    static final int COPIES_KEPT = 5;
    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmss.SSS'Z'")
            .withZone(ZoneOffset.UTC);

    private final StateFiles files;

    UndoCopies(StateFiles files) {
        this.files = files;
    }

    /** Writes the complete current state; @return the copy */
    Path keep() throws IOException {
        Path copy = files.undoFolder().resolve("previous-" + STAMP.format(Instant.now()) + ".zip");
        try {
            BackupArchive.write(copy, files.collect(false, true), ArchiveSignature.loadOrCreate(files.keyFile()));
        } catch (IOException e) {
            throw new IllegalStateException("cannot keep a copy of the current state in " + copy + " (" + e.getMessage()
                    + "); nothing changed");
        }
        try (Stream<Path> list = Files.list(files.undoFolder())) {
            List<Path> copies = list.filter(UndoCopies::isCopy).sorted(Comparator.reverseOrder()).toList();
            for (Path p : copies.subList(Math.min(COPIES_KEPT, copies.size()), copies.size())) {
                AtomicFiles.delete(p);
            }
        }
        return copy;
    }

    Optional<Path> newest() throws IOException {
        if (!Files.isDirectory(files.undoFolder())) {
            return Optional.empty();
        }
        try (Stream<Path> list = Files.list(files.undoFolder())) {
            return list.filter(UndoCopies::isCopy).max(Comparator.naturalOrder());
        }
    }

    private static boolean isCopy(Path p) {
        String n = p.getFileName().toString();
        return n.startsWith("previous-") && n.endsWith(".zip");
    }
}
