package org.tinysep.runtime.internal.log;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The files of one log in its folder: {@code <prefix>-<sequence of the first entry, 20 digits>.log}, so that name
 * order is write order. Applies the size bound (at most {@code maxFiles}) and the retention (files last written
 * before {@code now - maxAge}); the file being written is never deleted.
 */
final class LogFolder {

    private static final Logger LOG = LoggerFactory.getLogger(LogFolder.class);

    private final Path folder;
    private final String prefix;

    LogFolder(Path folder, String prefix) {
        this.folder = folder;
        this.prefix = prefix;
    }

    Path folder() {
        return folder;
    }

    String prefix() {
        return prefix;
    }

    /** @return the file for a new file starting at {@code firstSequence} */
    Path fileFor(long firstSequence) {
        return folder.resolve(String.format("%s-%020d.log", prefix, firstSequence));
    }

    /** @return the file of the entries kept per origin beside the rotating files ({@link OriginShare}) */
    Path perOriginFile() {
        return folder.resolve(prefix + "-per-origin.log");
    }

    /** @return the sequence of the first entry of one of {@link #files()}, from its name */
    static long firstSequence(Path file) {
        String name = file.getFileName().toString();
        return Long.parseLong(name.substring(name.length() - 24, name.length() - 4));
    }

    /** @return this log's files, oldest first; empty when the folder does not exist */
    List<Path> files() {
        List<Path> out = new ArrayList<>();
        if (!Files.isDirectory(folder)) {
            return out;
        }
        try (DirectoryStream<Path> dir = Files.newDirectoryStream(folder, prefix + "-*.log")) {
            for (Path p : dir) {
                if (p.getFileName().toString().matches("\\Q" + prefix + "\\E-\\d{20}\\.log")) {
                    out.add(p);
                }
            }
        } catch (IOException e) {
            LOG.warn("Cannot list the log folder {}: {}", folder, e.toString());
        }
        out.sort(null);
        return out;
    }

    /**
     * Deletes the oldest files beyond {@code maxFiles} and files last modified before {@code cutoff} (null: no
     * age limit), never {@code active}.
     *
     * @return how many files were deleted
     */
    int prune(int maxFiles, Instant cutoff, Path active) {
        List<Path> files = files();
        int deleted = 0;
        for (int i = 0; i < files.size(); i++) {
            Path f = files.get(i);
            if (f.equals(active)) {
                continue;
            }
            boolean tooMany = files.size() - i > maxFiles;
            if (tooMany || (cutoff != null && modified(f).isBefore(cutoff))) {
                try {
                    Files.deleteIfExists(f);
                    deleted++;
                    LOG.debug("Deleted log file {} ({})", f.getFileName(), tooMany ? "size bound" : "retention");
                } catch (IOException e) {
                    LOG.warn("Cannot delete log file {}: {}", f, e.toString());
                }
            }
        }
        return deleted;
    }

    private static Instant modified(Path f) {
        try {
            return Files.getLastModifiedTime(f).toInstant();
        } catch (NoSuchFileException e) {
            return Instant.MAX;
        } catch (IOException e) {
            return Instant.MAX; // unknown age: keep it
        }
    }
}
