package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * sd_notify for systemd's {@code Type=notify} and {@code WatchdogSec}: a real Unix datagram socket receives what the
 * launcher sends through {@code systemd-notify}. A few lines of Python play systemd's end, as systemd does: each
 * datagram is read with its passed file descriptors, which are closed ({@code systemd-notify} waits for that, its
 * "barrier", before it ends, so that systemd can still tell which service sent the message).
 */
class SdNotifyTest {

    private static final String SYSTEMD_END = String.join("\n",
            "import os, socket, sys",
            "s = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)",
            "s.bind(sys.argv[1])",
            "out = open(sys.argv[2], 'ab', buffering=0)",
            "while True:",
            "    msg, fds, flags, addr = socket.recv_fds(s, 4096, 16)",
            "    for fd in fds:",
            "        os.close(fd)",
            "    out.write(msg + b'\\n')");

    @TempDir
    Path tmp;

    @Test
    void watchdogAndReadyReachTheNotifySocketWithTheLaunchersPid() throws Exception {
        assumeTrue(onPath("python3") && onPath("systemd-notify"), "needs python3 and systemd-notify");
        Path socket = tmp.resolve("notify");
        Path received = tmp.resolve("received");
        Process systemd = new ProcessBuilder("python3", "-c", SYSTEMD_END, socket.toString(), received.toString())
                .redirectErrorStream(true).redirectOutput(tmp.resolve("receiver.log").toFile()).start();
        try {
            TestDistribution.await(Duration.ofSeconds(10), () -> Files.exists(socket), "the notify socket");
            SdNotify notify = SdNotify.fromEnvironment(Map.of(SdNotify.SOCKET_ENV, socket.toString())).orElseThrow();
            notify.ready("TinySEP up");
            assertTrue(notify.send("WATCHDOG=1"));
            TestDistribution.await(Duration.ofSeconds(10), () -> read(received).contains("WATCHDOG=1"), "WATCHDOG=1");
            String got = read(received);
            assertTrue(got.contains("READY=1") && got.contains("STATUS=TinySEP up"), got);
            assertTrue(got.contains("MAINPID=" + ProcessHandle.current().pid()), got);
        } finally {
            systemd.destroy();
        }
    }

    @Test
    void withoutSystemdNothingIsSentAndTheWatchdogRateIsHalfItsInterval() {
        assertEquals(Optional.empty(), SdNotify.fromEnvironment(Map.of()));
        assertEquals(Optional.of(Duration.ofSeconds(30)), SdNotify.watchdogInterval(Map.of(SdNotify.WATCHDOG_ENV,
                "60000000")));
        // systemd's rate wins when it asks for more often than the heartbeat's own interval (10 s)
        assertEquals(Duration.ofSeconds(5), Heartbeat.interval(Optional.of(Duration.ofSeconds(5))));
        assertEquals(Duration.ofSeconds(10), Heartbeat.interval(Optional.of(Duration.ofSeconds(30))));
        assertEquals(Duration.ofSeconds(Heartbeat.DEFAULT_SECONDS), Heartbeat.interval(Optional.empty()));
    }

    private static String read(Path file) {
        try {
            return Files.exists(file) ? Files.readString(file) : "";
        } catch (Exception e) {
            return "";
        }
    }

    private static boolean onPath(String tool) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(":")) {
            if (Files.isExecutable(Path.of(dir, tool))) {
                return true;
            }
        }
        return false;
    }
}
