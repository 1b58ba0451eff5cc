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

    private void write(List<Op> ops) {
        for (Op op : ops) {
            try {
                Path old = written.get(op.uid());
                if (op.backup() == null) {
                    if (old != null) {
                        files.delete(old);
                    }
                    written.remove(op.uid());
                } else {
                    Path now = files.write(op.backup());
                    written.put(op.uid(), now);
                    if (old != null && !old.equals(now)) {
                        files.delete(old);
                    }
                }
                op.done().forEach(f -> f.complete(null));
            } catch (Exception e) {
                problem.accept(op.uid(), e.toString());
                op.done().forEach(f -> f.completeExceptionally(e));
            }
        }
    }
}
