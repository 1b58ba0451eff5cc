package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.mail.SmtpSink;
import org.tinysep.tools.process.PlatformProcess;

/**
 * Issue 12 item 5, "the platform cannot die silently", without systemd: {@code java -jar tinysep.jar --supervise}
 * runs the real distribution as a child process. The test hangs the platform on purpose (SIGSTOP: the JVM is frozen,
 * as in a hang, and stops beating); the supervisor must see the heartbeat stop, kill the hung process and start a new
 * one, and the new platform must put the restart in the event log and mail it to the caregivers (an in-process SMTP
 * server) in plain words.
 */
class SupervisorIT {

    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm")
            .withZone(ZoneId.systemDefault());

    @TempDir
    Path tmp;

    @Test
    void aHungPlatformIsRestartedAndTheRestartIsLoggedAndMailed() throws Exception {
        Path home = tmp.resolve("home");
        new TestDistribution(home, null).realTime();
        try (SmtpSink smtp = new SmtpSink().start()) {
            Files.writeString(home.resolve("etc/org.tinysep.mailmanager.cfg"), "host=127.0.0.1\nport=" + smtp.port()
                    + "\nsecurity=NONE\nfrom=tinysep@localhost\nrecipients=carer@example.org\n");
            PlatformProcess p = PlatformProcess.launch(home, home, List.of("-Dtinysep.heartbeat.seconds=1",
                    "-D" + Supervisor.HANG_PROPERTY + "=6"), "--supervise");
            Long second = null;
            try {
                long first = pid(p.awaitLine("Supervisor: TinySEP started as process", Duration.ofSeconds(60)));
                p.awaitLine("bundles active", Duration.ofSeconds(120));
                Path var = home.resolve("var");
                TestDistribution.await(Duration.ofSeconds(60), () -> HeartbeatFile.read(var)
                        .filter(b -> b.pid() == first && "RUNNING".equals(b.state())).isPresent(), "a heartbeat");

                Instant hung = Instant.now();
                signal("-STOP", first); // the platform hangs
                String restart = p.awaitLine("Supervisor: TinySEP stopped responding", Duration.ofSeconds(60));
                Instant seen = Instant.now();
                long second0 = pid(p.awaitLine("Supervisor: TinySEP started as process", Duration.ofSeconds(60)));
                second = second0;
                System.out.printf("hung at %s, supervisor acted %.1f s later: %s%n", hung,
                        Duration.between(hung, seen).toMillis() / 1000.0, restart);
                assertTrue(ProcessHandle.of(first).map(h -> !h.isAlive()).orElse(true), "the hung process is gone");
                assertFalse(second0 == first);

                assertTrue(smtp.await(1, Duration.ofSeconds(120)), "a mail to the caregivers");
                SmtpSink.Received mail = smtp.messages().stream()
                        .filter(m -> m.subject().contains("restarted")).findFirst().orElseThrow();
                String body = mail.body().replace("\r\n", " ");
                System.out.println(mail.subject() + ": " + body);
                Matcher m = Pattern.compile("TinySEP was restarted at (\\d\\d:\\d\\d) after it stopped responding at "
                        + "(\\d\\d:\\d\\d)").matcher(body);
                assertTrue(m.find(), body);
                assertEquals(List.of("carer@example.org"), mail.to());
                assertTrue(m.group(2).equals(HH_MM.format(hung)) || m.group(2).equals(HH_MM.format(hung
                        .minusSeconds(2))), "the hang's time (last heartbeat): " + body);

                Optional<String> logged = awaitEventLine(var, "TinySEP was restarted at " + m.group(1)
                        + " after it stopped responding at " + m.group(2));
                assertTrue(logged.get().contains("PROBLEM"), logged.get());
                TestDistribution.await(Duration.ofSeconds(30), () -> !Files.exists(var.resolve(RestartNote.FILE)),
                        "the restart note deleted once mailed");
            } finally {
                p.process().destroy(); // SIGTERM to the supervisor: it stops the platform cleanly
                if (!p.process().waitFor(60, java.util.concurrent.TimeUnit.SECONDS)) {
                    p.process().destroyForcibly();
                }
                if (second != null) {
                    ProcessHandle.of(second).ifPresent(ProcessHandle::destroyForcibly);
                }
            }
        }
    }

    private static Optional<String> awaitEventLine(Path var, String text) {
        String[] found = new String[1];
        TestDistribution.await(Duration.ofSeconds(60), () -> {
            try (Stream<Path> files = Files.list(var.resolve("log"))) {
                for (Path f : files.filter(f -> f.getFileName().toString().startsWith("events-")).toList()) {
                    for (String line : Files.readAllLines(f)) {
                        if (line.contains(text)) {
                            found[0] = line;
                            return true;
                        }
                    }
                }
            } catch (IOException e) {
                return false;
            }
            return false;
        }, "'" + text + "' in the event log files");
        return Optional.of(found[0]);
    }

    private static long pid(String line) {
        Matcher m = Pattern.compile("process (\\d+)").matcher(line);
        assertTrue(m.find(), line);
        return Long.parseLong(m.group(1));
    }

    private static void signal(String signal, long pid) throws Exception {
        assertEquals(0, new ProcessBuilder("kill", signal, Long.toString(pid)).inheritIO().start().waitFor());
    }
}
