package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Predicate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * A log's {@link OriginShare} on disk: {@code <prefix>-per-origin.log} beside the rotating files, in the same line
 * format, written atomically before old files are pruned (at each new file, hourly) and when the log closes. So an
 * entry is in the rotating files, or, once they are pruned, among the newest {@code keepPerOrigin} of its origin
 * here. On open the file is read back and the entries written after it was saved are taken from the newest
 * rotating files. The writer thread adds; queries read.
 *
 * @param <E> the entry type
 */
final class OriginHistory<E> {

    private static final Logger LOG = LoggerFactory.getLogger(OriginHistory.class);

    private final OriginShare<E> share;
    private final Path file;
    private final LineCodec<E> codec;
    private final Clock clock;
    private final Comparator<E> order;
    private boolean dirty;

    private OriginHistory(OriginShare<E> share, Path file, LineCodec<E> codec, Clock clock) {
        this.share = share;
        this.file = file;
        this.codec = codec;
        this.clock = clock;
        this.order = Comparator.comparingLong(codec::sequence);
    }

    /** Reads the kept entries back, then those of the rotating files written after they were last saved. */
    static <E> OriginHistory<E> open(LogFolder folder, LineCodec<E> codec, LogSettings settings, Clock clock) {
        OriginHistory<E> h = new OriginHistory<>(new OriginShare<>(codec::origin, settings.keepPerOrigin(),
                settings.keepOrigins()), folder.perOriginFile(), codec, clock);
        if (settings.keepPerOrigin() > 0) {
            h.load(folder);
        }
        return h;
    }

    private void load(LogFolder folder) {
        LogReader<E> reader = new LogReader<>(folder, codec);
        long[] last = {0};
        if (Files.exists(file)) {
            Instant saved = modified();
            long damaged = reader.read(file, false, e -> {
                share.add(e, saved);
                last[0] = Math.max(last[0], codec.sequence(e));
            });
            if (damaged > 0) {
                LOG.warn("{} damaged lines in {} were skipped", damaged, file);
            }
        }
        List<Path> files = folder.files();
        int from = files.size();
        while (from > 0 && LogFolder.firstSequence(files.get(from - 1)) > last[0]) {
            from--;
        }
        from = Math.max(0, from - 1); // the file holding the entries just after the saved ones
        Instant now = clock.instant();
        for (int i = from; i < files.size(); i++) {
            reader.read(files.get(i), i == files.size() - 1, e -> {
                if (codec.sequence(e) > last[0]) {
                    share.add(e, now);
                }
            });
        }
    }

    private Instant modified() {
        try {
            return Files.getLastModifiedTime(file).toInstant();
        } catch (IOException e) {
            return clock.instant();
        }
    }

    /** An entry was written to the current file (writer thread). */
    void written(E entry) {
        share.add(entry, clock.instant());
        dirty = true;
    }

    /**
     * Before old files are pruned: forgets origins silent since {@code cutoff} (null: none) and saves the share
     * atomically if it changed (writer thread).
     */
    void save(Instant cutoff) {
        if (!share.enabled() || !(share.expire(cutoff) || dirty)) {
            return;
        }
        StringBuilder lines = new StringBuilder();
        for (E e : share.all(order)) {
            lines.append(codec.encode(e)).append('\n');
        }
        try {
            AtomicFiles.write(file, lines.toString().getBytes(StandardCharsets.UTF_8));
            dirty = false;
        } catch (IOException e) {
            LOG.warn("Cannot save the entries kept per origin in {}: {}", file, e.toString());
        }
    }

    /** @return the kept entries matching {@code filter} with a sequence below {@code floor}, oldest first */
    List<E> before(Predicate<E> filter, long floor) {
        return new ArrayList<>(share.matching(filter, e -> codec.sequence(e) < floor, order));
    }

    /** @return how many entries are kept */
    int size() {
        return share.size();
    }
}
