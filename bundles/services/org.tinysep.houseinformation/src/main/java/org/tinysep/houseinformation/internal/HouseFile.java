package org.tinysep.houseinformation.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The house file on disk. Writes are atomic (temp file in the same folder, fsync, atomic rename) and keep the
 * previous file as {@code <name>.bak}. A malformed file is moved aside to {@code <name>.broken-<timestamp>} and the
 * last good house is taken from the {@code .bak} (and written back); the last good house is never wiped.
 */
final class HouseFile {

    /** What loading found: the plan to use and, when the file was malformed, what went wrong. */
    record Load(HousePlan plan, String problem) {
    }

    private final Path file;
    private final Path backup;
    private final HouseCodec codec;
    /** Whether the file on disk is known good (loaded or written by us); only a good file becomes the .bak. */
    private volatile boolean diskIsGood;
    /** Test seam: runs after the temp file is written and synced, before it replaces the file. */
    Runnable beforeRename = () -> { };

    HouseFile(Path file, HouseCodec codec) {
        this.file = file.toAbsolutePath();
        this.backup = this.file.resolveSibling(this.file.getFileName() + ".bak");
        this.codec = codec;
    }

    Path path() {
        return file;
    }

    /** Loads the house; a missing file is an empty house. */
    Load load(Instant now) throws IOException {
        diskIsGood = false;
        if (!Files.exists(file)) {
            diskIsGood = true;
            return new Load(HousePlan.EMPTY, null);
        }
        try {
            HousePlan plan = codec.read(Files.readAllBytes(file), file.toString());
            diskIsGood = true;
            return new Load(plan, null);
        } catch (MalformedHouseException broken) {
            Path aside = AtomicFiles.moveAside(file, now);
            String problem = broken.getMessage() + "; moved aside to " + aside.getFileName();
            if (!Files.exists(backup)) {
                return new Load(HousePlan.EMPTY, problem + "; no " + backup.getFileName()
                        + ": starting with an empty house");
            }
            try {
                HousePlan good = codec.read(Files.readAllBytes(backup), backup.toString());
                replace(file, codec.write(good));
                diskIsGood = true;
                return new Load(good, problem + "; using the last good house from " + backup.getFileName() + " ("
                        + good.rooms().size() + " rooms)");
            } catch (MalformedHouseException alsoBroken) {
                return new Load(HousePlan.EMPTY, problem + "; the backup is unusable too (" + alsoBroken.getMessage()
                        + "): starting with an empty house");
            }
        }
    }

    /**
     * Saves the plan atomically; the file replaced becomes the {@code .bak} when it was good, else (it could not be
     * read or moved aside on load) it is moved aside, so a bad file never overwrites the last good house.
     */
    void save(HousePlan plan) throws IOException {
        byte[] bytes = codec.write(plan);
        Files.createDirectories(file.getParent());
        if (Files.exists(file)) {
            if (diskIsGood) {
                replace(backup, Files.readAllBytes(file));
            } else {
                AtomicFiles.moveAside(file, Instant.now());
            }
        }
        replace(file, bytes);
        diskIsGood = true;
    }

    /** Writes {@code bytes} to a temp file next to {@code target}, syncs it, renames it over {@code target}. */
    private void replace(Path target, byte[] bytes) throws IOException {
        AtomicFiles.write(target, bytes, beforeRename);
    }
}
