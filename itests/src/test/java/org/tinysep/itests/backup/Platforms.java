package org.tinysep.itests.backup;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import org.tinysep.tools.process.DistributionCopy;
import org.tinysep.tools.process.PlatformProcess;

/**
 * The real distribution ({@code runtime/org.tinysep.launcher/target/tinysep}, system property {@code tinysep.dist})
 * for the backup tests: copied to a test folder and started as its own process ({@link PlatformProcess}) with the
 * platform's log at INFO.
 */
final class Platforms {

    private static final List<String> INFO_LOG = List.of("-Dorg.slf4j.simpleLogger.defaultLogLevel=info");

    private Platforms() {
    }

    /** @return the distribution folder to copy */
    static Path distribution() {
        Path dist = Path.of(System.getProperty("tinysep.dist", "../runtime/org.tinysep.launcher/target/tinysep"));
        try {
            return DistributionCopy.require(dist);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Copies the distribution (without var/) to {@code home}. */
    static void install(Path home) throws IOException {
        DistributionCopy.copy(distribution(), home);
    }

    /** Starts the platform in {@code home} (its log there too) and waits until its shell answers. */
    static PlatformProcess start(Path home) throws IOException {
        return start(home, home);
    }

    /** Starts {@code home}'s tinysep.jar with {@code launcherArgs}, its log in {@code logDir}; waits for the shell. */
    static PlatformProcess start(Path home, Path logDir, String... launcherArgs) throws IOException {
        return PlatformProcess.start(home, logDir, INFO_LOG, launcherArgs);
    }
}
