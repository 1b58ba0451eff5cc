package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.mqtt.Mosquitto;
import org.tinysep.testsupport.mqtt.MqttTestClient;
import org.tinysep.tools.process.PlatformProcess;

/**
 * Issue 15: the real distribution as a process, its MQTT bridge configured for a real Mosquitto broker. When the
 * platform is killed (SIGKILL: nothing can say goodbye), the broker publishes the bridge's Last Will: the retained
 * {@code tinysep/<flat>/status} becomes {@code offline}, which a board that connects later still sees.
 */
class MqttLastWillIT {

    private static final Duration WAIT = Duration.ofSeconds(120);

    @TempDir
    Path tmp;

    @Test
    void aKilledPlatformIsReportedOfflineByItsLastWill() throws Exception {
        Path home = tmp.resolve("home");
        new TestDistribution(home, null);
        try (Mosquitto broker = Mosquitto.startDefault();
                MqttTestClient board = MqttTestClient.connect(broker.url(), "board").subscribe("tinysep/+/status",
                        "tinysep/+/platform")) {
            Files.writeString(home.resolve("etc/org.tinysep.mqtt.cfg"), "brokerUrl=" + broker.url()
                    + "\nflatId=flat-kill\nallowAnonymous=true\n"); // the test broker lets anyone in
            try (PlatformProcess p = PlatformProcess.start(home)) {
                board.await("tinysep/flat-kill/status", "online", WAIT);
                board.await("tinysep/flat-kill/platform", "\"flat\":\"flat-kill\"", WAIT);
                board.clear();
                p.kill();
            }
            MqttTestClient.Received will = board.await("tinysep/flat-kill/status", "offline", WAIT);
            System.out.println("after the kill: " + will);
            try (MqttTestClient later = MqttTestClient.connect(broker.url(), "later")) {
                later.subscribe("tinysep/flat-kill/status");
                MqttTestClient.Received retained = later.await("tinysep/flat-kill/status", "offline", WAIT);
                assertEquals(true, retained.retained(), "the offline status is retained");
            }
        }
    }
}
