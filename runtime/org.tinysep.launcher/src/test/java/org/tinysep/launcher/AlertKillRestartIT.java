package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.tools.process.PlatformProcess;

/**
 * Issue 12 item 3 with the real distribution as a process: an inactivity alert raised (bathroom limit 1 min, real
 * time) is OPEN in {@code tinysep:alerts}; the platform is killed with SIGKILL; after the restart the same alert is
 * still OPEN (kept by the alert service in {@code var/alerts/alerts.properties}), the event log says it was
 * restored, and {@code tinysep:ack} closes it.
 */
class AlertKillRestartIT {

    private static final Duration WAIT = Duration.ofSeconds(150);

    @TempDir
    Path tmp;

    @Test
    void anAlertOpenBeforeAKillMinus9IsOpenAfterTheRestart() throws Exception {
        Path home = tmp.resolve("home");
        BathroomFlat flat = BathroomFlat.create(home);
        Files.writeString(home.resolve("etc/org.tinysep.alerts.cfg"), "contacts=first@care.test, second@care.test\n"
                + "summaryTime=\ntimeZone=UTC\n");
        Path state = home.resolve("var/alerts/alerts.properties");
        try (AmicaSender sender = flat.sender()) {
            AmicaSender.Node bath = BathroomFlat.bathroomNode(sender);
            try (PlatformProcess p = PlatformProcess.start(home)) {
                bath.keepAlive();
                BathroomFlat.moveInBathroom(p, bath, null, WAIT); // until the flat is OCCUPIED and watched
                TestDistribution.await(WAIT, () -> p.text("tinysep:alerts").contains("alert 1  OPEN"),
                        "alert 1 open");
                TestDistribution.await(WAIT, () -> read(state).contains("state=OPEN"), "the alert saved");
                System.out.println("before the kill:\n" + p.text("tinysep:alerts"));
                p.kill();
            }
            try (PlatformProcess p = PlatformProcess.start(home)) {
                String alerts = p.text("tinysep:alerts");
                System.out.println("after the restart:\n" + alerts);
                assertTrue(alerts.contains("alert 1  OPEN  INACTIVITY"), alerts);
                assertTrue(alerts.contains("TinySEP: no activity in Bathroom since"), alerts);
                String log = p.text("tinysep:log 400");
                assertTrue(log.contains("restored after a restart: 1 open alert(s)"), log);
                String ack = p.text("tinysep:ack 1 Anna");
                assertTrue(ack.contains("alert 1 acknowledged by Anna"), ack);
                assertTrue(p.text("tinysep:alerts").contains("(no open alerts)"));
            }
        }
    }

    private static String read(Path file) {
        try {
            return Files.isRegularFile(file) ? Files.readString(file) : "";
        } catch (IOException e) {
            return "";
        }
    }
}
