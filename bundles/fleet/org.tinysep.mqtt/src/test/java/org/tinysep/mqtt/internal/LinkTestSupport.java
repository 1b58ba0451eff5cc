package org.tinysep.mqtt.internal;

import java.nio.file.Path;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.io.TempDir;

/** What the tests of the Paho link share: a state folder, the bridge's executor (one thread), the recorded events. */
abstract class LinkTestSupport {

    @TempDir
    Path var;

    final ExecutorService executor = Executors.newSingleThreadExecutor();
    final RecordingEvents events = new RecordingEvents();

    @AfterEach
    void stopExecutor() {
        executor.shutdownNow();
    }
}
