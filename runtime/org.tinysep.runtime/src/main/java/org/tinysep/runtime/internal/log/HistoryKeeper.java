package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.time.Clock;
import java.util.List;
import java.util.function.Predicate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.LogHistory;

/**
 * A log service's link to its {@link PersistentLog}: opened on activation (reloading the ring), reopened when the
 * settings change, closed on deactivation. Without a usable folder the log works in memory only and queries
 * search the ring.
 *
 * @param <E> the entry type
 */
final class HistoryKeeper<E> {

    private static final Logger LOG = LoggerFactory.getLogger(HistoryKeeper.class);

    private final RingBuffer<E> ring;
    private final LineCodec<E> codec;
    private final String prefix;
    private final Clock clock;
    private final long beatMillis;
    private volatile PersistentLog<E> history;
    private LogSettings settings;

    /** @param beatMillis the writer's beat (0: woken by the first entry of a pause), see {@link PersistentLog} */
    HistoryKeeper(RingBuffer<E> ring, LineCodec<E> codec, String prefix, Clock clock, long beatMillis) {
        this.beatMillis = beatMillis;
        this.ring = ring;
        this.codec = codec;
        this.prefix = prefix;
        this.clock = clock;
    }

    /**
     * Uses {@code next} from now on (null: memory only). The first time, the ring is reloaded from the files.
     *
     * @return the damaged lines skipped while reloading (0 when nothing was reloaded)
     */
    synchronized long apply(LogSettings next) {
        boolean first = settings == null && history == null;
        if (next != null && next.equals(settings) && history != null) {
            return 0;
        }
        close();
        settings = next;
        if (next == null || next.folder() == null) {
            return 0;
        }
        try {
            history = PersistentLog.open(ring, codec, prefix, next, clock, first && ring.lastSequence() == 0,
                    beatMillis, PersistentLog.writerThread(prefix));
            return history.loadedDamaged();
        } catch (IOException | RuntimeException e) {
            LOG.warn("Cannot keep the {} history in {}: {}; the log works in memory only", prefix, next.folder(),
                    e.toString());
            return 0;
        }
    }

    /** After each append, with the appended entry. */
    void signal(E appended) {
        PersistentLog<E> h = history;
        if (h != null) {
            h.signal(codec.sequence(appended));
        }
    }

    /** @return the newest matching entries from the files and the ring, or from the ring alone */
    LogHistory<E> query(Predicate<E> filter, int limit) {
        PersistentLog<E> h = history;
        if (h != null) {
            return h.query(filter, limit);
        }
        List<E> all = ring.newest(Integer.MAX_VALUE).stream().filter(filter).toList();
        return new LogHistory<>(all.subList(Math.max(0, all.size() - limit), all.size()), all.size(), 0);
    }

    /** @return the open history, or null */
    PersistentLog<E> history() {
        return history;
    }

    synchronized void close() {
        PersistentLog<E> h = history;
        history = null;
        if (h != null) {
            h.close();
        }
    }
}
