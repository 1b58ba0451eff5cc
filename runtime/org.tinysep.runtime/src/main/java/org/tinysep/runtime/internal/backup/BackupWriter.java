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
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.AtomicBatch;

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
        CompletableFuture<Void> done = enqueue("\u0000flush-marker", null); // a delete of nothing, queued last
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
            }
            write(ops);
        }
    }

    /**
     * Writes one batch: each file atomically (temp, forced, renamed), then each folder synced once (a group commit:
     * a burst of device creations costs one folder sync per driver, not one per device); the futures complete
     * after the sync, so a completed save is durable.
     */
    private void write(List<Op> ops) {
        List<Op> done = new ArrayList<>(ops.size());
        for (Op op : ops) {
            try {
                Path old = written.get(op.uid());
                if (op.backup() == null) {
                    if (old != null) {
                        batch.delete(old);
                    }
                    written.remove(op.uid());
                } else {
                    Path now = files.write(op.backup(), batch);
                    written.put(op.uid(), now);
                    if (old != null && !old.equals(now)) {
                        batch.delete(old);
                    }
                }
                done.add(op);
            } catch (Exception e) {
                problem.accept(op.uid(), e.toString());
                op.done().forEach(f -> f.completeExceptionally(e));
            }
        }
        batch.commit();
        done.forEach(op -> op.done().forEach(f -> f.complete(null)));
    }

    /** @return folder syncs so far (one per folder per batch; tests check a burst does not sync per file) */
    long foldersSynced() {
        synchronized (writing) {
            return batch.foldersSynced();
        }
    }
}
