package org.tinysep.device.support.files;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Many crash-safe file replacements committed as a group. Each {@link #write} writes a temp file beside its target;
 * {@link #commit} then forces every temp file to disk, renames each atomically over its target, does the deletes
 * (in the order they were asked, after the renames before them) and syncs every folder touched, once. After a crash
 * or a kill each target holds its old or its new content, never a mix; leftover {@code *.tmp} files are the reader's
 * to delete (the backup store does on load).
 * <p>
 * Why a group: forcing the temp files one after the other, after all were written, lets the file system commit their
 * data in one journal commit (the first force), so a burst of 10,000 device backups costs about one disk flush, not
 * 10,000 (each took 10-670 ms on a busy shared disk); and 2 folder syncs instead of 10,000.
 * Not thread-safe: one writer thread uses one batch.
 */
public final class AtomicBatch {

    /** A step of the commit: a temp file to rename over its target, or (tmp null) a file to delete. */
    private record Step(Path tmp, Path target) {
    }

    private final List<Step> steps = new ArrayList<>();
    private final Set<Path> folders = new LinkedHashSet<>();
    private final Map<Path, IOException> failed = new LinkedHashMap<>();
    private long foldersSynced;
    private long filesCommitted;

    /** Writes {@code bytes} to a temp file beside {@code target} (creating its folder); in place after {@link #commit}. */
    public void write(Path target, byte[] bytes) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        AtomicFiles.createPrivateDirectories(dir);
        Path tmp = Files.createTempFile(dir, target.getFileName() + ".", ".tmp");
        try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
            ByteBuffer buf = ByteBuffer.wrap(bytes);
            while (buf.hasRemaining()) {
                ch.write(buf);
            }
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(tmp);
            throw e;
        }
        steps.add(new Step(tmp, target));
        folders.add(dir);
    }

    /** Deletes {@code file} if present, at {@link #commit} (after the renames asked before). */
    public void delete(Path file) {
        steps.add(new Step(null, file));
    }

    /**
     * Forces every temp file, renames each over its target, deletes, syncs every folder touched once. The targets
     * that could not be written or deleted (their old content is intact) are in {@link #failures()}.
     */
    public void commit() {
        failed.clear();
        for (Step s : steps) {
            if (s.tmp() != null) {
                try (FileChannel ch = FileChannel.open(s.tmp(), StandardOpenOption.WRITE)) {
                    ch.force(true);
                } catch (IOException e) {
                    failed.put(s.target(), e);
                }
            }
        }
        for (Step s : steps) {
            try {
                if (s.tmp() == null) {
                    if (Files.deleteIfExists(s.target())) {
                        folders.add(s.target().toAbsolutePath().getParent());
                    }
                } else if (failed.containsKey(s.target())) {
                    Files.deleteIfExists(s.tmp());
                } else {
                    Files.move(s.tmp(), s.target(), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                    filesCommitted++;
                }
            } catch (IOException e) {
                failed.put(s.target(), e);
            }
        }
        steps.clear();
        for (Path dir : folders) {
            AtomicFiles.syncDirectory(dir);
            foldersSynced++;
        }
        folders.clear();
    }

    /** @return the targets the last {@link #commit} could not write or delete, each with its reason */
    public Map<Path, IOException> failures() {
        return Map.copyOf(failed);
    }

    /** @return folder syncs made by this batch's commits so far (the cost a burst saves) */
    public long foldersSynced() {
        return foldersSynced;
    }

    /** @return files renamed into place by this batch's commits so far */
    public long filesCommitted() {
        return filesCommitted;
    }
}
