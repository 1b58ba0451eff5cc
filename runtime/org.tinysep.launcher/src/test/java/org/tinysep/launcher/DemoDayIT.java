package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.tools.process.Ports;

/**
 * Issue 32 item 3 (the demo clock) with the real {@code ./run.sh}, distribution and simulator: the demo day is
 * played up to {@code TINYSEP_DEMO_UNTIL} and the platform's clock then stays there (EXTERNAL, no return to real
 * time), so the console shows the demo day as it was; {@code tinysep:time real} returns to real time.
 */
class DemoDayIT {

    private static final Path REPO = Path.of("").toAbsolutePath().resolve("../..").normalize();
    private static final String PROMPT = "g! ";

    @TempDir
    Path root;

    /** A scratch checkout: run.sh, the script, a copy of the distribution with free ports, the simulator. */
    private void scratchCheckout() throws Exception {
        Path dist = root.resolve("runtime/org.tinysep.launcher/target/tinysep");
        new TestDistribution(dist, null);
        try (var shipped = Files.list(Path.of("src/main/dist/etc"))) { // etc/ as shipped: the demo picks its ports
            for (Path f : Files.list(dist.resolve("etc")).toList()) {
                Files.delete(f);
            }
            for (Path f : shipped.toList()) {
                Files.copy(f, dist.resolve("etc").resolve(f.getFileName()));
            }
        }
        // ports nobody holds now (on a shared machine another TinySEP may hold the shipped ones: then the demo would
        // rightly refuse, DemoFlatScriptTest)
        Path etc = dist.resolve("etc");
        Files.writeString(etc.resolve("org.tinysep.amica.busradio.udp.cfg"), "port=" + Ports.freeUdp() + "\nbindAddress=127.0.0.1\n");
        Files.writeString(etc.resolve("org.tinysep.sunspot.busradio.cfg"),
                "udpPort=" + Ports.freeUdp() + "\nudpBindAddress=127.0.0.1\n");
        Files.writeString(etc.resolve("org.tinysep.timecontroller.cfg"), "syncPort=" + Ports.freeUdp() + "\n");
        Files.copy(REPO.resolve("run.sh"), root.resolve("run.sh"));
        Files.createDirectories(root.resolve("scripts"));
        Files.copy(REPO.resolve("scripts/demo-flat.sh"), root.resolve("scripts/demo-flat.sh"));
        Files.createSymbolicLink(root.resolve("simulator"), REPO.resolve("simulator"));
    }

    @Test
    void theClockStaysOnTheDemoDayAtTheGivenHour() throws Exception {
        scratchCheckout();
        Map<String, String> env = Map.of("SKIP_BUILD", "1", "TZ", "UTC", "TINYSEP_DEMO_FROM", "06:30",
                "TINYSEP_DEMO_UNTIL", "07:00", "TINYSEP_DEMO_DIR", root.resolve("demo").toString(),
                "TINYSEP_VAR", root.resolve("var").toString());
        try (ShellProcess tinysep = new ShellProcess("./run.sh", root, env)) {
            String console = tinysep.await(0, s -> s.contains("DEMO: the simulated day is played")
                    || s.contains("DEMO: the demo day was NOT sent") || s.contains("FAILED"), Duration.ofSeconds(240),
                    "the end of the demo day");
            System.out.println("=== the console of a demo start ===\n" + console);
            assertTrue(console.contains("DEMO: the simulated day is played up to 07:00; the clock stays there"),
                    console);
            assertTrue(console.contains("Web console: http://127.0.0.1:"), "the bound address is said: " + console);
            // the simulator plays the platform's day, or the next one once its 06:30 has passed (UTC)
            java.time.LocalDateTime now = java.time.LocalDateTime.now(ZoneOffset.UTC);
            LocalDate date = now.toLocalTime().isBefore(java.time.LocalTime.of(6, 30)) ? now.toLocalDate()
                    : now.toLocalDate().plusDays(1);
            String day = date + "T06:59:59Z"; // the last second the span 06:30-07:00 plays
            String time = ask(tinysep, "tinysep:time");
            assertTrue(time.contains("mode       EXTERNAL") && time.contains("now        " + day), time);
            Thread.sleep(5_000); // no TICK comes any more: the clock is held, it neither runs nor jumps back
            time = ask(tinysep, "tinysep:time");
            assertTrue(time.contains("mode       EXTERNAL") && time.contains("now        " + day), time);
            time = ask(tinysep, "tinysep:time real");
            assertTrue(time.contains("mode       REAL"), time);
            assertFalse(time.contains("now        " + day), time);
            tinysep.type("stop 0");
            assertEquals(0, tinysep.waitFor(Duration.ofSeconds(60)), tinysep.output());
            assertFalse(tinysep.output().contains("FAILED"), tinysep.output());
        }
    }

    @Test
    void stoppingThePlatformEarlyStopsTheSimulatorWithIt() throws Exception {
        scratchCheckout();
        Map<String, String> env = Map.of("SKIP_BUILD", "1", "TZ", "UTC", "TINYSEP_DEMO_FROM", "00:00",
                "TINYSEP_DEMO_UNTIL", "24:00", "TINYSEP_DEMO_DIR", root.resolve("demo").toString(),
                "TINYSEP_VAR", root.resolve("var").toString());
        try (ShellProcess tinysep = new ShellProcess("./run.sh", root, env)) {
            tinysep.await(0, s -> s.contains(PROMPT), Duration.ofSeconds(180), "the shell prompt");
            // the simulator is running (or about to): its log names it
            Path log = root.resolve("demo/simulator.log");
            long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
            while (!(Files.exists(log) && Files.readString(log).contains("platform time")) && System.nanoTime() < deadline) {
                Thread.sleep(200);
            }
            assertTrue(simulatorRunning(), () -> "the simulator runs during the demo day; its log: "
                    + (Files.exists(log) ? readQuietly(log) : "(none)") + "\nthe console: " + tinysep.output());
            tinysep.type("stop 0");
            assertEquals(0, tinysep.waitFor(Duration.ofSeconds(60)), tinysep.output());
            deadline = System.nanoTime() + Duration.ofSeconds(10).toNanos();
            while (simulatorRunning() && System.nanoTime() < deadline) {
                Thread.sleep(200);
            }
            assertFalse(simulatorRunning(), "the simulator stopped with the platform");
            Thread.sleep(3_000);
            assertFalse(tinysep.output().contains("FAILED") || tinysep.output().contains("NOT sent"), tinysep.output());
        }
    }

    private static String readQuietly(Path file) {
        try {
            return Files.readString(file);
        } catch (java.io.IOException e) {
            return "(unreadable: " + e.getMessage() + ")";
        }
    }

    /** @return whether a simulator of this test's demo (its key file on the command line) is running */
    private boolean simulatorRunning() {
        String key = root.resolve("demo/var/sync.key").toString();
        return ProcessHandle.allProcesses().anyMatch(p -> p.info().commandLine().map(c -> c.contains(key)
                && c.contains("org.tinysep.simulator")).orElse(false));
    }

    private static String ask(ShellProcess tinysep, String command) throws Exception {
        int mark = tinysep.length();
        tinysep.type(command);
        String since = tinysep.await(mark, s -> s.contains(PROMPT), Duration.ofSeconds(60), "the answer to " + command);
        return since.substring(0, since.indexOf(PROMPT));
    }
}
