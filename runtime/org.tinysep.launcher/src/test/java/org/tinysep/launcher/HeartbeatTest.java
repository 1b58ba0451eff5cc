package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The heartbeat is fed only while the liveness check passes: a check that hangs (a deadlock inside the platform)
 * or fails stops it, although the heartbeat's own timer thread is fine.
 */
class HeartbeatTest {

    @TempDir
    Path var;

    @Test
    void aHangingLivenessCheckStopsTheHeartbeatAndAnAnsweringOneFeedsIt() throws Exception {
        CountDownLatch hang = new CountDownLatch(1);
        AtomicBoolean healthy = new AtomicBoolean(false);
        Heartbeat.Probe probe = () -> {
            if (!healthy.get()) {
                hang.await(); // the platform does not answer
            }
        };
        try (Heartbeat beat = new Heartbeat(probe, new HeartbeatFile(var), Optional.empty(), Duration.ofMillis(100))) {
            beat.start();
            TestDistribution.await(Duration.ofSeconds(30), beat::failing, "the hang noticed");
            assertTrue(HeartbeatFile.read(var).isEmpty(), "no heartbeat while the check hangs");

            healthy.set(true);
            hang.countDown(); // it answers again
            TestDistribution.await(Duration.ofSeconds(30), () -> HeartbeatFile.read(var).isPresent(), "a heartbeat");
            assertEquals("RUNNING", HeartbeatFile.read(var).orElseThrow().state());
            assertEquals(ProcessHandle.current().pid(), HeartbeatFile.read(var).orElseThrow().pid());
        }
    }

    @Test
    void aFailingCheckStopsTheHeartbeat() {
        Heartbeat.Probe probe = () -> {
            throw new IllegalStateException("the event log is not running");
        };
        try (Heartbeat beat = new Heartbeat(probe, new HeartbeatFile(var), Optional.empty(), Duration.ofMillis(100))) {
            beat.start();
            TestDistribution.await(Duration.ofSeconds(30), beat::failing, "the failure noticed");
            assertTrue(HeartbeatFile.read(var).isEmpty());
        }
    }
}
