package org.tinysep.runtime.internal.log;

import java.time.Clock;
import java.time.Instant;
import java.util.List;
import java.util.function.BiPredicate;
import java.util.function.IntSupplier;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * What the event log and the packet log share, written once: an in-memory ring of entries stamped with the
 * platform time (the Time Controller while one is bound), kept on disk by a {@link HistoryKeeper} through the
 * entry's {@link LineCodec} and reloaded on start; queries over the files; the capacity from the configuration.
 * Appending is O(1) and does no I/O on the caller's thread. The subclasses add their {@code record} method and what
 * they do with damaged lines; their time-controller reference comes from here (bnd
 * {@code -dsannotations-options: inherit}).
 *
 * @param <E> the entry
 */
abstract class LogService<E> {

    /** Builds the entry with the sequence number the ring gives it, stamped with {@code time}. */
    interface Entry<E> {
        E make(long sequence, Instant time);
    }

    private final LogClock clock;
    private final RingBuffer<E> ring;
    private final HistoryKeeper<E> history;
    private final String capacityKey;
    private final BiPredicate<LogQuery, E> matcher;

    /**
     * @param fallback    the clock while no Time Controller is bound
     * @param capacity    the ring's first capacity
     * @param codec       the entry's file lines
     * @param prefix      the files' name prefix, e.g. {@code events}
     * @param capacityKey the configuration key of the capacity, for its messages
     * @param matcher     whether an entry matches a query ({@code LogQuery::matches})
     * @param beatMillis  how the file writer is woken: 0 by the first entry of a pause, else on its own beat of
     *                    that period while entries come ({@link Cadence})
     */
    LogService(Clock fallback, int capacity, LineCodec<E> codec, String prefix, String capacityKey,
            BiPredicate<LogQuery, E> matcher, long beatMillis) {
        this.clock = new LogClock(fallback);
        this.ring = new RingBuffer<>(capacity);
        this.history = new HistoryKeeper<>(ring, codec, prefix, Clock.systemUTC(), beatMillis);
        this.capacityKey = capacityKey;
        this.matcher = matcher;
    }

    /** Sizes the ring; a bad value keeps the current size (see {@link Capacity}). */
    void configure(IntSupplier capacity) {
        ring.resize(Capacity.read(capacityKey, capacity, ring.capacity()));
    }

    /** Activation and modification: sizes the ring and keeps the files as configured. */
    final void reconfigure(IntSupplier capacity, LogSettings settings) {
        configure(capacity);
        persist(settings);
    }

    /** Keeps the history in files as {@code settings} say, reporting damaged lines (see {@link #keep}). */
    abstract void persist(LogSettings settings);

    /**
     * Keeps the history in files as {@code settings} say (null: memory only); the first call reloads the ring.
     *
     * @return how many damaged lines of the files were skipped
     */
    final long keep(LogSettings settings) {
        return history.apply(settings);
    }

    /** Writes what is left and forces it to the disk. */
    void closeHistory() {
        history.close();
    }

    /**
     * Stamps, numbers and stores an entry, and tells the writer (see {@link PersistentLog#signal}).
     *
     * @return the entry as stored
     */
    final E append(Entry<E> entry) {
        Instant time = clock.now(); // outside the ring's lock: it may call the Time Controller
        E e = ring.append(seq -> entry.make(seq, time));
        history.signal(e);
        return e;
    }

    @Reference(name = "timeController", cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    void bindTimeController(TimeControllerProvider provider) {
        clock.use(provider);
    }

    void unbindTimeController(TimeControllerProvider provider) {
        clock.release(provider);
    }

    public List<E> recent(int max) {
        return ring.newest(max);
    }

    /** Searches the files (and what is not written yet); memory only: the ring. */
    public LogHistory<E> query(LogQuery query) {
        return history.query(e -> matcher.test(query, e), query.limit());
    }

    /** @return the history on disk, or null when the log works in memory only */
    PersistentLog<E> persistent() {
        return history.history();
    }

    int capacity() {
        return ring.capacity();
    }
}
