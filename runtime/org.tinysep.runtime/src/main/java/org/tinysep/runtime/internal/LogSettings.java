package org.tinysep.runtime.internal;

import java.nio.file.Path;
import java.time.Duration;

/**
 * Where and how a log keeps its history on disk.
 *
 * @param folder       the folder of the log files, or null for no files (memory only)
 * @param maxFileBytes a file is closed and a new one started before it would grow beyond this
 * @param maxFiles     at most this many files per log; the oldest are deleted first
 * @param maxAge       files last written longer ago than this are deleted; {@link Duration#ZERO} keeps them
 * @param syncInterval how often written entries are forced to the disk (fsync)
 */
record LogSettings(Path folder, long maxFileBytes, int maxFiles, Duration maxAge, Duration syncInterval) {

    static final long DEFAULT_MAX_FILE_BYTES = 8L * 1024 * 1024;
    static final int DEFAULT_MAX_FILES = 16;
    static final Duration DEFAULT_MAX_AGE = Duration.ofDays(30);
    static final Duration DEFAULT_SYNC = Duration.ofSeconds(2);

    LogSettings {
        if (maxFileBytes < 1024 || maxFiles < 2 || maxAge.isNegative() || syncInterval.isNegative()
                || syncInterval.isZero()) {
            throw new IllegalArgumentException("bad log settings " + maxFileBytes + " " + maxFiles + " " + maxAge
                    + " " + syncInterval);
        }
    }

    /** @return the defaults, writing into {@code folder} */
    static LogSettings in(Path folder) {
        return new LogSettings(folder, DEFAULT_MAX_FILE_BYTES, DEFAULT_MAX_FILES, DEFAULT_MAX_AGE, DEFAULT_SYNC);
    }
}
