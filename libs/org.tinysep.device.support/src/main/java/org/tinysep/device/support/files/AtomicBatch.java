package org.tinysep.device.support.files;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileAttribute;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Many crash-safe file replacements committed as a group. Each {@link #write} writes a temp file beside its target;
 * {@link #commit} then forces every temp file to disk, renames each atomically over its target, does the deletes
 * (in the order they were asked, after the renames before them) and syncs every folder touched, once. After a crash
 * or a kill each target holds its old or its new content, never a mix; leftover {@code *.tmp} files are the reader's
 * to delete (the backup store does on load).
 * <p>
 * Why a group: 2 folder syncs instead of 10,000 for a burst of 10,000 device backups, and the forces of a group are
 * made {@value #FORCERS} at a time ({@link #commit}'s own short-lived threads): the file system's journal then
 * commits the forces waiting together in one go, where forces one after the other each waited for a journal commit of
 * their own (ext4 on this project's shared build machine, 1,000 files: 1.4-3.6 ms per file one after the other while
 * the disk was busy, 0.17 ms 8 at a time; 0.1 ms and 0.04-0.06 ms when it was quiet. Issue 29).
 * Not thread-safe: one writer thread uses one batch.
 */
public final class AtomicBatch {

    /** A step of the commit: a temp file to rename over its target, or (tmp null) a file to delete. */
    private record Step(Path tmp, Path target) {
    }

    /** Forces made at once by a commit of many files. */
    static final int FORCERS = 8;
    /** A commit with fewer temp files than this forces them on its own thread. */
    static final int PARALLEL_FROM = 4;
    private static final Set<StandardOpenOption> CREATE_NEW_WRITE = Set.of(StandardOpenOption.CREATE_NEW,
            StandardOpenOption.WRITE);
    /** Temp files are {@code rw-------} on POSIX, as the files they replace. */
    private static final FileAttribute<?>[] PRIVATE = FileSystems.getDefault().supportedFileAttributeViews()
            .contains("posix") ? new FileAttribute<?>[] {PosixFilePermissions.asFileAttribute(AtomicFiles.PRIVATE_FILE)}
                    : new FileAttribute<?>[0];

    /** How a temp file is forced to disk (tests: a slow disk that counts the forces at once). */
    interface Force {
        void force(Path tmp) throws IOException;
    }

    private final Force force;
    private final List<Step> steps = new ArrayList<>();
    private final Set<Path> folders = new LinkedHashSet<>();
    private final Map<Path, IOException> failed = new LinkedHashMap<>();
    private long foldersSynced;
    private long filesCommitted;

    public AtomicBatch() {
        this(AtomicBatch::forceFile);
    }

    AtomicBatch(Force force) {
        this.force = force;
    }

    private static void forceFile(Path tmp) throws IOException {
        try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
            ch.force(true);
        }
    }

    /** Writes {@code bytes} to a temp file beside {@code target} (creating its folder); in place after {@link #commit}. */
    public void write(Path target, byte[] bytes) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        AtomicFiles.createPrivateDirectories(dir);
        // created and written through one open: a temp file made first (Files.createTempFile) and opened again to be
        // truncated and written cost two opens, a random name and, on ext4, a flush at the close (its heuristic for a
        // file replaced by truncation): ~30 % of the backup writer's time while 20,000 devices were created (issue 29)
        Path tmp = null;
        FileChannel ch = null;
        while (ch == null) {
            tmp = dir.resolve(target.getFileName() + "." + Long.toHexString(System.nanoTime()) + ".tmp");
            try {
                ch = FileChannel.open(tmp, CREATE_NEW_WRITE, PRIVATE);
            } catch (FileAlreadyExistsException leftover) {
                // a temp file of that name is there (an earlier run's, left by a crash): take the next name
            }
        }
        try (FileChannel open = ch) {
            ByteBuffer buf = ByteBuffer.wrap(bytes);
            while (buf.hasRemaining()) {
                open.write(buf);
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
        failed.putAll(forceAll(steps.stream().filter(s -> s.tmp() != null).toList()));
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

    /** @return the targets whose temp file could not be forced, each with its reason */
    private Map<Path, IOException> forceAll(List<Step> writes) {
        Map<Path, IOException> bad = new ConcurrentHashMap<>();
        if (writes.size() < PARALLEL_FROM) {
            writes.forEach(s -> forceOne(s, bad));
            return bad;
        }
        AtomicInteger next = new AtomicInteger();
        boolean[] forced = new boolean[writes.size()];
        Callable<Void> forcer = () -> {
            for (int i = next.getAndIncrement(); i < writes.size(); i = next.getAndIncrement()) {
                forceOne(writes.get(i), bad);
                forced[i] = true;
            }
            return null;
        };
        int threads = Math.min(FORCERS, writes.size() / 2);
        ExecutorService pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "tinysep-atomic-force");
            t.setDaemon(true);
            return t;
        });
        try {
            pool.invokeAll(Collections.nCopies(threads, forcer));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // the files not forced yet keep their old content (below)
        } finally {
            pool.shutdownNow();
        }
        // the forcers' writes happen-before invokeAll's return; after an interrupted wait a file seen unforced is
        // taken as not forced (its old content stays), never the other way round
        for (int i = 0; i < forced.length; i++) {
            if (!forced[i]) {
                bad.putIfAbsent(writes.get(i).target(), new IOException("not forced: the commit was interrupted"));
            }
        }
        return Map.copyOf(bad);
    }

    private void forceOne(Step s, Map<Path, IOException> bad) {
        try {
            force.force(s.tmp());
        } catch (IOException e) {
            bad.put(s.target(), e);
        }
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
