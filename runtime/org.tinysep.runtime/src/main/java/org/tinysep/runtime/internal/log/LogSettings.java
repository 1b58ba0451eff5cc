package org.tinysep.runtime.internal.log;

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
 * @param keepPerOrigin the newest entries of each origin kept beside the rotating files ({@link OriginShare}); 0: none
 * @param keepOrigins  at most this many node origins, and this many other origins, have such a share
 */
record LogSettings(Path folder, long maxFileBytes, int maxFiles, Duration maxAge, Duration syncInterval,
        int keepPerOrigin, int keepOrigins) {

    static final long DEFAULT_MAX_FILE_BYTES = 8L * 1024 * 1024;
    static final int DEFAULT_MAX_FILES = 16;
    static final Duration DEFAULT_MAX_AGE = Duration.ofDays(30);
    static final Duration DEFAULT_SYNC = Duration.ofSeconds(2);
    static final int DEFAULT_KEEP_PER_ORIGIN = 20;
    static final int DEFAULT_KEEP_ORIGINS = 1000;

    LogSettings {
        if (maxFileBytes < 1024 || maxFiles < 2 || maxAge.isNegative() || syncInterval.isNegative()
                || syncInterval.isZero() || keepPerOrigin < 0 || keepOrigins < 1) {
            throw new IllegalArgumentException("bad log settings " + maxFileBytes + " " + maxFiles + " " + maxAge
                    + " " + syncInterval);
        }
    }

    /** The default share per origin. */
    LogSettings(Path folder, long maxFileBytes, int maxFiles, Duration maxAge, Duration syncInterval) {
        this(folder, maxFileBytes, maxFiles, maxAge, syncInterval, DEFAULT_KEEP_PER_ORIGIN, DEFAULT_KEEP_ORIGINS);
    }

    /** @return the defaults, writing into {@code folder} */
    static LogSettings in(Path folder) {
        return new LogSettings(folder, DEFAULT_MAX_FILE_BYTES, DEFAULT_MAX_FILES, DEFAULT_MAX_AGE, DEFAULT_SYNC);
    }
}
