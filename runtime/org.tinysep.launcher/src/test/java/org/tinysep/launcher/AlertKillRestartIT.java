package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.testsupport.process.PlatformProcess;

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
        new TestDistribution(home, null);
        int port = freeUdpPort();
        Files.writeString(home.resolve("etc/" + TestDistribution.UDP_PID + ".cfg"),
                "port=" + port + "\nbindAddress=127.0.0.1\n");
        Files.writeString(home.resolve("etc/org.tinysep.timecontroller.cfg"),
                "mode=REAL\nsyncPort=0\nsyncBindAddress=127.0.0.1\n");
        Files.writeString(home.resolve("etc/org.tinysep.inactivity.cfg"), "roomLimits=Bathroom=1\ntimeZone=UTC\n");
        Files.writeString(home.resolve("etc/org.tinysep.alerts.cfg"), "contacts=first@care.test, second@care.test\n"
                + "summaryTime=\ntimeZone=UTC\n");
        Files.writeString(home.resolve("etc/org.tinysep.houseinformation.placement.cfg"), "placements=1.40=Bathroom\n");
        Files.createDirectories(home.resolve("var"));
        Files.writeString(home.resolve("var/house.xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <HOUSE_ROOMS>
                    <ROOM><UID>b1000000-0000-4000-8000-000000000001</UID><NAME>Hall</NAME><TYPE>Hall</TYPE>
                        <NEIGHBORS><ROOM_UID>b1000000-0000-4000-8000-000000000002</ROOM_UID></NEIGHBORS></ROOM>
                    <ROOM><UID>b1000000-0000-4000-8000-000000000002</UID><NAME>Bathroom</NAME><TYPE>Bathroom</TYPE>
                        <NEIGHBORS><ROOM_UID>b1000000-0000-4000-8000-000000000001</ROOM_UID></NEIGHBORS></ROOM>
                </HOUSE_ROOMS>
                """);
        Path state = home.resolve("var/alerts/alerts.properties");
        try (DatagramSocket socket = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            InetSocketAddress radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
            try (PlatformProcess p = PlatformProcess.start(home)) {
                send(socket, radio, 0, new KeepAlive(120, 2900, 0x0A11,
                        AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242));
                int[] seq = {1};
                // motion until the flat is OCCUPIED and watched (placement is applied in the background)
                TestDistribution.await(WAIT, () -> {
                    try {
                        send(socket, radio, seq[0]++, new MotionDetection(true));
                        Thread.sleep(500);
                    } catch (IOException | InterruptedException e) {
                        throw new IllegalStateException(e);
                    }
                    return p.text("tinysep:devices").contains("state=WATCHING");
                }, "Inactivity Recognition watching the bathroom");
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

    private static void send(DatagramSocket socket, InetSocketAddress radio, int sequence, AmicaPayload payload)
            throws IOException {
        byte[] b = AmicaCodec.encode(new AmicaFrame(1, 40, AmicaCodec.PLATFORM_ADDRESS, sequence & 0xFF,
                AmicaPayloads.encode(payload)));
        socket.send(new DatagramPacket(b, b.length, radio));
    }

    private static String read(Path file) {
        try {
            return Files.isRegularFile(file) ? Files.readString(file) : "";
        } catch (IOException e) {
            return "";
        }
    }

    private static int freeUdpPort() {
        try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
