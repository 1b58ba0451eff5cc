package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Predicate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Reads the files of a {@link LogFolder} back into entries. A line that cannot be decoded is damaged: it is
 * counted and skipped, never stops the reading. The last line of the newest file without its line feed is an
 * entry being written right now (or torn by a crash): it is skipped and not counted; anywhere else it counts as
 * damaged. A file deleted while being read is skipped.
 *
 * @param <E> the entry type
 */
final class LogReader<E> {

    private static final Logger LOG = LoggerFactory.getLogger(LogReader.class);

    /**
     * What a scan found; {@code firstSequence} is the smallest sequence read ({@link Long#MAX_VALUE} when none), so
     * that older entries kept elsewhere ({@link OriginShare}) can be added without doubles.
     */
    record Result<E>(List<E> entries, long matched, long damaged, long firstSequence, long lastSequence) {
    }

    private final LogFolder folder;
    private final LineCodec<E> codec;

    LogReader(LogFolder folder, LineCodec<E> codec) {
        this.folder = folder;
        this.codec = codec;
    }

    /** @return the newest {@code limit} entries matching {@code filter} over all files, oldest first */
    Result<E> query(Predicate<E> filter, int limit) {
        Deque<E> kept = new ArrayDeque<>();
        long[] matched = {0};
        long[] last = {0};
        long[] first = {Long.MAX_VALUE};
        long damaged = 0;
        List<Path> files = folder.files();
        for (int i = 0; i < files.size(); i++) {
            damaged += read(files.get(i), i == files.size() - 1, e -> {
                last[0] = Math.max(last[0], codec.sequence(e));
                first[0] = Math.min(first[0], codec.sequence(e));
                if (filter.test(e)) {
                    matched[0]++;
                    kept.addLast(e);
                    if (kept.size() > limit) {
                        kept.removeFirst();
                    }
                }
            });
        }
        return new Result<>(new ArrayList<>(kept), matched[0], damaged, first[0], last[0]);
    }

    /** @return the newest {@code limit} entries, reading only as many files (newest first) as needed */
    Result<E> newest(int limit) {
        List<Path> files = folder.files();
        Deque<E> kept = new ArrayDeque<>();
        long damaged = 0;
        long last = 0;
        long first = Long.MAX_VALUE;
        for (int i = files.size() - 1; i >= 0 && kept.size() < limit; i--) {
            List<E> inFile = new ArrayList<>();
            damaged += read(files.get(i), i == files.size() - 1, inFile::add);
            for (int j = inFile.size() - 1; j >= 0 && kept.size() < limit; j--) {
                kept.addFirst(inFile.get(j));
            }
            for (E e : inFile) {
                last = Math.max(last, codec.sequence(e));
                first = Math.min(first, codec.sequence(e));
            }
        }
        return new Result<>(new ArrayList<>(kept), kept.size(), damaged, first, last);
    }

    /** @return the number of damaged lines in {@code file}; every good entry goes to {@code sink} in file order */
    long read(Path file, boolean newest, Consumer<E> sink) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            return 0; // pruned meanwhile
        } catch (IOException e) {
            LOG.warn("Cannot read log file {}: {}", file, e.toString());
            return 0;
        }
        long damaged = 0;
        int start = 0;
        while (start < bytes.length) {
            int end = start;
            while (end < bytes.length && bytes[end] != '\n') {
                end++;
            }
            boolean terminated = end < bytes.length;
            if (end > start && (terminated || !newest)) {
                String line = new String(bytes, start, end - start, StandardCharsets.UTF_8);
                try {
                    sink.accept(codec.decode(line));
                } catch (IllegalArgumentException | NullPointerException e) {
                    damaged++;
                }
            }
            start = end + 1;
        }
        return damaged;
    }
}
