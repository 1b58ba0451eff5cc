package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * Base of the in-process tests that restart the distribution with its state folder outside it ({@code --var}):
 * before each test a fresh copy in {@code tmp/home} with its state in {@code tmp/state}, not started yet; after it
 * the platform is stopped. Written once for DriversListIT and WebUploadRestartIT.
 */
abstract class StateFolderFixture {

    @TempDir
    Path tmp;
    TestDistribution dist;

    @BeforeEach
    void copyDistribution() throws IOException {
        dist = new TestDistribution(tmp.resolve("home"), tmp.resolve("state"));
    }

    @AfterEach
    void stopDistribution() {
        if (dist != null) {
            dist.stop();
        }
    }
}
