package org.tinysep.runtime.internal.log;

import java.io.BufferedOutputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Clock;
import java.time.Instant;
import java.util.List;

/**
 * Appends log entries to the newest file of a {@link LogFolder}, one line each, starting a new file before one
 * would exceed the size bound (then pruning old files). {@link #write} ends with a flush to the operating system;
 * {@link #sync} forces the file to the disk. Each line goes to the 64 KiB buffer in one call, and the buffer hands
 * the OS only whole calls (a line longer than the buffer goes in one write of its own), so a process crash never
 * leaves half a line from a completed write; a line torn by power loss is ended by {@link #repairTornLine} and
 * skipped as damaged. Not thread-safe: one writer thread.
 *
 * @param <E> the entry type
 */
final class LogFileWriter<E> implements AutoCloseable {

    private final LogFolder folder;
    private final LineCodec<E> codec;
    private final LogSettings settings;
    private final Clock clock;
    private final OriginHistory<E> kept;
    private Path current;
    private FileOutputStream file;
    private OutputStream out;
    private long size;
    private boolean dirty;
    private long bytesWritten;

    /** @param kept the entries kept per origin: told of every entry written, saved before files are pruned */
    LogFileWriter(LogFolder folder, LineCodec<E> codec, LogSettings settings, Clock clock, OriginHistory<E> kept)
            throws IOException {
        this.folder = folder;
        this.codec = codec;
        this.settings = settings;
        this.clock = clock;
        this.kept = kept;
        org.tinysep.device.support.files.AtomicFiles.createPrivateDirectories(folder.folder());
        List<Path> files = folder.files();
        if (!files.isEmpty()) {
            Path last = files.get(files.size() - 1);
            if (Files.size(last) < settings.maxFileBytes()) {
                open(last);
                repairTornLine(last);
            }
        }
    }

    /** Appends the entries and flushes them to the operating system. */
    void write(List<E> entries) throws IOException {
        for (E e : entries) {
            byte[] line = (codec.encode(e) + "\n").getBytes(StandardCharsets.UTF_8);
            if (out == null || (size > 0 && size + line.length > settings.maxFileBytes())) {
                rotate(codec.sequence(e));
            }
            out.write(line);
            kept.written(e);
            size += line.length;
            bytesWritten += line.length;
        }
        if (out != null) {
            out.flush();
            dirty = true;
        }
    }

    /** Forces what was written to the disk, if anything was written since the last sync. */
    void sync() throws IOException {
        if (dirty && file != null) {
            file.getChannel().force(false);
            dirty = false;
        }
    }

    /**
     * Deletes files beyond the size bound and the retention, after saving the entries kept per origin (so what
     * the deleted files held of each origin's newest entries stays on disk).
     */
    void prune() {
        Instant cutoff = settings.maxAge().isZero() ? null : clock.instant().minus(settings.maxAge());
        kept.save(cutoff);
        folder.prune(settings.maxFiles(), cutoff, current);
    }

    /** @return the bytes written by this writer, for measurements */
    long bytesWritten() {
        return bytesWritten;
    }

    Path current() {
        return current;
    }

    @Override
    public void close() throws IOException {
        if (out != null) {
            out.flush();
            sync();
            out.close();
            out = null;
            file = null;
        }
    }

    /** Closes the file and saves the entries kept per origin. */
    void closeAndSave() throws IOException {
        close();
        kept.save(null);
    }

    private void rotate(long firstSequence) throws IOException {
        close();
        open(folder.fileFor(firstSequence));
        prune();
    }

    private void open(Path path) throws IOException {
        file = new FileOutputStream(org.tinysep.device.support.files.AtomicFiles.createPrivateFile(path).toFile(), true);
        out = new BufferedOutputStream(file, 64 * 1024);
        current = path;
        size = Files.size(path);
    }

    /** A crash may leave a last line without its line feed: end it, so the next entry starts on a new line. */
    private void repairTornLine(Path path) throws IOException {
        if (size == 0) {
            return;
        }
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.READ)) {
            java.nio.ByteBuffer last = java.nio.ByteBuffer.allocate(1);
            ch.read(last, size - 1);
            if (last.get(0) != '\n') {
                out.write('\n');
                out.flush();
                size++;
            }
        }
    }
}
