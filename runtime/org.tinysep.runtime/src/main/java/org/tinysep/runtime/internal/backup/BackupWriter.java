package org.tinysep.runtime.internal.backup;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import java.util.function.Function;
import java.util.function.Predicate;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.files.AtomicBatch;

/**
 * Writes backups on the store's own thread: saves of one component before its write are coalesced (the newest
 * wins), a delete is ordered with the writes of the same component. Callers never wait for the disk unless they
 * wait on the returned future.
 */
final class BackupWriter {

    /** One queued operation: the backup to write, or null to delete. */
    private record Op(String uid, ComponentBackup backup, List<CompletableFuture<Void>> done) {
    }

    private final BackupFiles files;
    private final ScheduledExecutorService executor;
    private final long delayMillis;
    private final BiConsumer<String, String> problem;
    private final Map<String, Op> pending = new LinkedHashMap<>();
    /** Where each component's file is, as last written or loaded; used only on the writer thread. */
    private final Map<String, Path> written;
    private boolean scheduled;
    private static final String FLUSH_MARKER = "\u0000flush-marker";
    /** Operations in the batch being written (for {@link #backlog}). */
    private volatile int inFlight;
    /** System.nanoTime() after which a stopping store writes no more refreshes of backups already on disk. */
    private volatile long stopBy;
    /** System.nanoTime() after which it writes no more backups that have no file yet; valid once newLimited. */
    private volatile long stopByNew;
    private volatile boolean newLimited;
    private volatile boolean stopping;
    /** Saves of backups with no file yet dropped because the stop's limit passed. */
    private volatile int notSaved;
    /** Refreshes of backups on disk dropped because the stop's limit passed (their older file stays). */
    private volatile int notRefreshed;
    /** Serialises drains (the executor's, and the caller's on stop or reload), so writes of one UID keep order. */
    private final Object writing = new Object();
    /** The group commit of each drain; used under {@link #writing}. */
    private final AtomicBatch batch = new AtomicBatch();

    BackupWriter(BackupFiles files, Map<String, Path> written, ScheduledExecutorService executor, long delayMillis,
            BiConsumer<String, String> problem) {
        this.files = files;
        this.written = written;
        this.executor = executor;
        this.delayMillis = delayMillis;
        this.problem = problem;
    }

    CompletableFuture<Void> write(ComponentBackup b) {
        return enqueue(b.uid(), b);
    }

    CompletableFuture<Void> delete(String uid) {
        return enqueue(uid, null);
    }

    /** @return completes once everything queued before is on disk; writes at once, without the delay */
    CompletableFuture<Void> flush() {
        CompletableFuture<Void> done = enqueue(FLUSH_MARKER, null); // a delete of nothing, queued last
        try {
            executor.execute(this::drain);
        } catch (RuntimeException stopping) {
            drain(); // the store is stopping: write on the caller
        }
        return done;
    }

    private synchronized CompletableFuture<Void> enqueue(String uid, ComponentBackup b) {
        CompletableFuture<Void> f = new CompletableFuture<>();
        Op old = pending.remove(uid);
        List<CompletableFuture<Void>> done = old == null ? new ArrayList<>() : old.done();
        done.add(f);
        pending.put(uid, new Op(uid, b, done));
        if (!scheduled) {
            scheduled = true;
            try {
                executor.schedule(this::drain, delayMillis, TimeUnit.MILLISECONDS);
            } catch (RuntimeException stopping) {
                scheduled = false;
                f.completeExceptionally(new IllegalStateException("the backup store is stopped"));
            }
        }
        return f;
    }

    /** Writes everything queued; runs on the executor, or on the caller when the store stops. */
    void drain() {
        synchronized (writing) {
            List<Op> ops;
            synchronized (this) {
                ops = new ArrayList<>(pending.values());
                pending.clear();
                scheduled = false;
                inFlight = ops.size();
            }
            try {
                write(ops);
            } finally {
                inFlight = 0;
            }
        }
    }

    /**
     * The store is stopping: refreshes of backups already on disk not begun by {@code refreshBy} are dropped (their
     * older file stays), and so are saves of backups with no file yet not begun by {@code newBy} (0: no limit yet);
     * each counted.
     */
    void stopBy(long refreshBy, long newBy) {
        stopBy = refreshBy;
        stopByNew = newBy;
        newLimited = newBy != 0;
        stopping = true;
    }

    /** @return saves of backups with no file yet dropped because the stop's limit passed */
    int notSaved() {
        return notSaved;
    }

    /** @return refreshes of saved backups dropped because the stop's limit passed */
    int notRefreshed() {
        return notRefreshed;
    }

    private boolean late(String uid) {
        if (!stopping) {
            return false;
        }
        long now = System.nanoTime();
        return written.containsKey(uid) ? now - stopBy > 0 : newLimited && now - stopByNew > 0;
    }

    /** @return saves and deletes not yet on disk: queued, or in the batch being written */
    synchronized int backlog() {
        return pending.size() + inFlight - (pending.containsKey(FLUSH_MARKER) ? 1 : 0);
    }

    /**
     * Writes one batch as a group commit ({@link AtomicBatch}): every file written, then all forced together,
     * renamed into place, each folder synced once; the futures complete after that, so a completed save is durable.
     */
    private void write(List<Op> ops) {
        Map<Path, Op> byFile = new LinkedHashMap<>();
        for (Op op : stopping ? neverSavedFirst(ops, Op::uid, written::containsKey) : ops) {
            if (late(op.uid())) {
                if (op.uid().equals(FLUSH_MARKER)) {
                    // nothing to count
                } else if (written.containsKey(op.uid())) {
                    notRefreshed++;
                } else {
                    notSaved++;
                }
                IllegalStateException late = new IllegalStateException("not saved: the stop's time limit passed");
                op.done().forEach(f -> f.completeExceptionally(late)); // reported once, as a count, by the store
                continue;
            }
            try {
                Path old = written.get(op.uid());
                if (op.backup() == null) {
                    if (old != null) {
                        batch.delete(old);
                    }
                    written.remove(op.uid());
                } else {
                    Path now = files.write(op.backup(), batch);
                    byFile.put(now, op);
                    written.put(op.uid(), now);
                    if (old != null && !old.equals(now)) {
                        batch.delete(old);
                    }
                }
            } catch (Exception e) {
                failed(op, e);
            }
        }
        batch.commit();
        batch.failures().forEach((file, e) -> {
            Op op = byFile.get(file);
            if (op != null) {
                written.remove(op.uid()); // the file holds its old content, if any
                failed(op, e);
            }
        });
        ops.forEach(op -> op.done().forEach(f -> f.complete(null)));
    }

    /**
     * While the store stops against its time limit, backups with no file on disk yet (devices created in a burst
     * just before the stop) are written before refreshes of ones already saved: a refresh not written loses only
     * the last few seconds of state (the older file stays), a new device not written would be lost.
     *
     * @return the same operations, those whose UID has no file yet first, each group in its order
     */
    static <T> List<T> neverSavedFirst(List<T> ops, Function<T, String> uid, Predicate<String> onDisk) {
        List<T> out = new ArrayList<>(ops.size());
        List<T> later = new ArrayList<>();
        for (T op : ops) {
            (onDisk.test(uid.apply(op)) ? later : out).add(op);
        }
        out.addAll(later);
        return out;
    }

    private void failed(Op op, Exception e) {
        problem.accept(op.uid(), e.toString());
        op.done().forEach(f -> f.completeExceptionally(e));
    }

    /** @return folder syncs so far (one per folder per batch; tests check a burst does not sync per file) */
    long foldersSynced() {
        synchronized (writing) {
            return batch.foldersSynced();
        }
    }
}
