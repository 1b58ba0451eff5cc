package org.tinysep.runtime.internal.log;

import java.nio.file.Path;
import java.time.Duration;
import org.osgi.framework.BundleContext;
import org.tinysep.device.support.files.StateFolder;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.runtime.internal.RuntimeConfig;

/**
 * Reads the log-history settings of {@link RuntimeConfig}, rejecting bad values with a WARN and their default.
 * The folder is the configured {@code logDirectory}, else {@code ${tinysep.var}/log}, else
 * {@code ${tinysep.home}/var/log}, else the bundle's data area {@code log}.
 */
final class LogConfig {

    private static final Logger LOG = LoggerFactory.getLogger(LogConfig.class);

    private LogConfig() {
    }

    /** @return the settings, or null when persistence is switched off or no folder can be found */
    static LogSettings read(RuntimeConfig config, BundleContext context) {
        if (!config.logPersistence()) {
            return null;
        }
        Path folder = folder(config.logDirectory(), context);
        if (folder == null) {
            LOG.warn("No folder for the log history (no tinysep.var, tinysep.home or bundle data area); "
                    + "the logs work in memory only");
            return null;
        }
        long kb = Capacity.read("logMaxFileSizeKb", config::logMaxFileSizeKb, 1, 1_048_576, 8192);
        int files = Capacity.read("logMaxFiles", config::logMaxFiles, 2, 10_000, LogSettings.DEFAULT_MAX_FILES);
        int days = Capacity.read("logRetentionDays", config::logRetentionDays, 0, 36_500, 30);
        int sync = Capacity.read("logSyncMillis", config::logSyncMillis, 10, 3_600_000, 2000);
        int perOrigin = Capacity.read("logKeepPerOrigin", config::logKeepPerOrigin, 0, 10_000,
                LogSettings.DEFAULT_KEEP_PER_ORIGIN);
        int origins = Capacity.read("logKeepOrigins", config::logKeepOrigins, 1, 100_000,
                LogSettings.DEFAULT_KEEP_ORIGINS);
        return new LogSettings(folder, Math.max(1024, kb * 1024), files, Duration.ofDays(days),
                Duration.ofMillis(sync), perOrigin, origins);
    }

    static Path folder(String configured, BundleContext context) {
        return StateFolder.resolveOrDataArea(configured, context, "log");
    }
}
