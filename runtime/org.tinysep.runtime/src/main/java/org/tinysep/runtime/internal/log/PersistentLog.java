package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.time.Clock;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.LogHistory;
import org.tinysep.runtime.internal.Threads;

/**
 * The on-disk history of one log ring. Appending stays on the caller's thread and O(1) (the ring); one writer
 * thread drains the ring in batches into the log files, each batch flushed to the operating system in whole lines
 * (see {@link LogFileWriter}). The writer wakes either {@value #WRITE_DELAY_MILLIS} ms after the first new entry (the event log: each pause's
 * first entry schedules it), or on its own beat while entries keep coming ({@link Cadence}, the packet log: the
 * receive thread hands it nothing). It forces the file to the disk every {@link LogSettings#syncInterval()} and
 * prunes old files at each new file and hourly. Queries read the files (and the ring for what is not written yet)
 * on the caller's thread.
 *
 * @param <E> the entry type
 */
final class PersistentLog<E> implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PersistentLog.class);
    /**
     * How long the writer waits after the first new entry before it writes: entries arriving meanwhile go out in
     * the same batch, so a steady trickle of packets costs one wake-up and one write per interval, not per packet.
     */
    static final long WRITE_DELAY_MILLIS = 50;
    /** Empty beats after which a {@link Cadence} stops until the next entry. */
    static final int IDLE_BEATS = 4;

    private final RingBuffer<E> ring;
    private final LineCodec<E> codec;
    private final LogReader<E> reader;
    private final LogFileWriter<E> writer;
    private final OriginHistory<E> kept;
    private final ScheduledThreadPoolExecutor thread;
    private final RingDrain<E> drain;
    /** the writer's own beat; null: woken by the first entry after a pause */
    private final Cadence cadence;
    private final long loadedDamaged;
    private final long syncMillis;
    /** A sync is scheduled for what was written since the last one. */
    private volatile boolean syncDue;
    private volatile boolean failing;

    private PersistentLog(RingBuffer<E> ring, LineCodec<E> codec, LogFolder folder, LogSettings settings,
            Clock clock, long loadedDamaged, long beatMillis, ScheduledThreadPoolExecutor thread) throws IOException {
        this.ring = ring;
        this.codec = codec;
        this.reader = new LogReader<>(folder, codec);
        this.loadedDamaged = loadedDamaged;
        this.kept = OriginHistory.open(folder, codec, settings, clock);
        this.writer = new LogFileWriter<>(folder, codec, settings, clock, kept);
        this.thread = thread;
        thread.setExecuteExistingDelayedTasksAfterShutdownPolicy(false); // close() drains what is left
        this.drain = new RingDrain<>(ring, codec::sequence,
                task -> thread.schedule(task, WRITE_DELAY_MILLIS, TimeUnit.MILLISECONDS), this::write,
                "written to " + folder.prefix() + " files");
        this.cadence = beatMillis <= 0 ? null
                : new Cadence(drain, thread, beatMillis, IDLE_BEATS, () -> ring.capacityHint() / 4);
        this.syncMillis = settings.syncInterval().toMillis(); // a sync follows a write, none while idle
        thread.scheduleWithFixedDelay(writer::prune, 0, 1, TimeUnit.HOURS);
    }

    /**
     * Opens the history in {@code settings.folder()} under {@code prefix}; if {@code reload}, the ring (which must
     * be empty) is first filled with the newest entries found there and numbering goes on after them.
     *
     * @throws IOException when the folder cannot be created or the newest file cannot be opened
     */
    static <E> PersistentLog<E> open(RingBuffer<E> ring, LineCodec<E> codec, String prefix, LogSettings settings,
            Clock clock, boolean reload) throws IOException {
        return open(ring, codec, prefix, settings, clock, reload, 0, writerThread(prefix));
    }

    /**
     * @param beatMillis 0: the writer wakes {@value #WRITE_DELAY_MILLIS} ms after the first entry of a pause;
     *                   else it drains on its own beat of that period while entries come ({@link Cadence})
     * @param thread     the writer thread (tests pass one that counts what it is handed)
     */
    static <E> PersistentLog<E> open(RingBuffer<E> ring, LineCodec<E> codec, String prefix, LogSettings settings,
            Clock clock, boolean reload, long beatMillis, ScheduledThreadPoolExecutor thread) throws IOException {
        LogFolder folder = new LogFolder(settings.folder(), prefix);
        long damaged = 0;
        if (reload) {
            LogReader.Result<E> history = new LogReader<>(folder, codec).newest(ring.capacity());
            ring.restore(history.entries(), history.lastSequence());
            damaged = history.damaged();
            LOG.info("Loaded {} {} entries from {} (last sequence {}, {} damaged lines skipped)",
                    history.entries().size(), prefix, settings.folder(), history.lastSequence(), damaged);
        }
        return new PersistentLog<>(ring, codec, folder, settings, clock, damaged, beatMillis, thread);
    }

    static ScheduledThreadPoolExecutor writerThread(String prefix) {
        return new ScheduledThreadPoolExecutor(1, Threads.named("tinysep-" + prefix + "-writer"));
    }

    /** @return whether the writer's own beat is running (false when it has none) */
    boolean beating() {
        return cadence != null && cadence.running();
    }

    /** @return the damaged lines skipped while reloading */
    long loadedDamaged() {
        return loadedDamaged;
    }

    /** Called after each append with the entry's sequence: the writer thread will write it soon. */
    void signal(long sequence) {
        if (cadence != null) {
            cadence.signal(sequence);
        } else {
            drain.signal();
        }
    }

    /**
     * @return the newest {@code limit} entries matching {@code filter}: those kept per origin from files pruned
     *         since ({@link OriginHistory}), the files, then what is not written yet
     */
    LogHistory<E> query(Predicate<E> filter, int limit) {
        LogReader.Result<E> files = reader.query(filter, limit);
        List<E> unwritten = ring.after(files.lastSequence(), Integer.MAX_VALUE);
        long floor = Math.min(files.firstSequence(), unwritten.isEmpty() ? Long.MAX_VALUE
                : codec.sequence(unwritten.get(0)));
        List<E> all = kept.before(filter, floor);
        long matched = files.matched() + all.size();
        all.addAll(files.entries());
        for (E e : unwritten) {
            if (filter.test(e)) {
                all.add(e);
                matched++;
            }
        }
        return new LogHistory<>(all.subList(Math.max(0, all.size() - limit), all.size()), matched, files.damaged());
    }

    /** @return how many entries are kept per origin beside the files */
    int keptPerOrigin() {
        return kept.size();
    }

    /** @return bytes written to files so far */
    long bytesWritten() {
        return writer.bytesWritten();
    }

    /** @return how many entries were overwritten in the ring before the writer could write them */
    long skipped() {
        return drain.skipped();
    }

    /** Writes what is left, forces it to the disk and closes the file. Waits up to 5 s for the writer thread. */
    @Override
    public void close() {
        thread.shutdown();
        try {
            if (!thread.awaitTermination(5, TimeUnit.SECONDS)) {
                LOG.warn("The {} writer did not finish within 5 s", codec.getClass().getSimpleName());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        drain.drain(); // the entries recorded after the last scheduled drain
        try {
            writer.closeAndSave();
        } catch (IOException e) {
            LOG.warn("Could not close the log file {}: {}", writer.current(), e.toString());
        }
    }

    /** Flushes what the writer thread wrote so far and forces it to the disk (tests and benchmarks). */
    void flush() {
        try {
            thread.submit(() -> {
                drain.drain();
                sync();
            }).get(30, TimeUnit.SECONDS);
        } catch (Exception e) {
            LOG.warn("Log flush failed: {}", e.toString());
        }
    }

    private void write(List<E> batch) {
        try {
            writer.write(batch);
            syncLater();
            if (failing) {
                failing = false;
                LOG.info("Writing log files works again ({})", writer.current());
            }
        } catch (IOException e) {
            if (!failing) {
                failing = true;
                LOG.warn("Cannot write log file {}: {}; entries stay in memory only until it works again",
                        writer.current(), e.toString());
            }
        }
    }

    /** Forces what was written to the disk {@code syncInterval} after the first write since the last sync. */
    private void syncLater() {
        if (syncDue) {
            return;
        }
        syncDue = true;
        try {
            thread.schedule(() -> {
                syncDue = false;
                sync();
            }, syncMillis, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            syncDue = false; // closing: close() saves the file
        }
    }

    /** @return tasks waiting on the writer thread (for tests: an idle log keeps only its hourly prune) */
    int waitingTasks() {
        return thread.getQueue().size();
    }

    private void sync() {
        try {
            writer.sync();
        } catch (IOException e) {
            LOG.warn("Cannot force log file {} to disk: {}", writer.current(), e.toString());
        }
    }
}
