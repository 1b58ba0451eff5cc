package org.tinysep.itests.backup;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.tinysep.tools.process.PlatformProcess;
import org.tinysep.tools.process.Ports;

/**
 * Issue 10.3 / 17.5, "demo then real mode": the demo of {@code ./run.sh} runs in its own throwaway state and leaves
 * the user's installation as it was. With the real distribution as processes and the real scripts: a user's
 * installation (its etc/ with its own ports, its state folder) gets the demo prepared ({@code scripts/demo-flat.sh
 * prepare}), the platform runs the demo from the demo folder ({@code --home/--var}) in EXTERNAL time, where a local
 * user without the key cannot send a TICK; the script's simulator plays a short span and says BYE, so the clock
 * returns to REAL; the user's etc/ and var/ are byte for byte as before; the next ordinary start is in REAL time.
 */
public class DemoThenRealModeTest {

    private static final Path SCRIPT = Path.of("..", "scripts", "demo-flat.sh").toAbsolutePath().normalize();

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @Test
    public void theDemoLeavesTheInstallationAsItWasAndTheNextStartIsInRealTime() throws Exception {
        Path home = tmp.newFolder("home").toPath();
        Platforms.install(home);
        int amica = Ports.freeUdp();
        int sunSpot = Ports.freeUdp();
        int sync = Ports.freeUdp();
        Path etc = home.resolve("etc");
        Files.writeString(etc.resolve("org.tinysep.amica.busradio.udp.cfg"), "port=" + amica + "\nbindAddress=127.0.0.1\n");
        Files.writeString(etc.resolve("org.tinysep.sunspot.busradio.cfg"),
                "udpPort=" + sunSpot + "\nudpBindAddress=127.0.0.1\n");
        Files.writeString(etc.resolve("org.tinysep.timecontroller.cfg"), "syncPort=" + sync + "\n"); // the user's port
        Files.createDirectories(home.resolve("var"));
        Files.writeString(home.resolve("var/notes.txt"), "the user's own state\n");
        Map<String, String> before = snapshot(home);
        Path demo = tmp.getRoot().toPath().resolve("demo");
        Path logs = tmp.newFolder("logs").toPath();

        assertEquals("no hardware: the demo is wanted", 0, script(Map.of(), "wanted", home).exit);
        Result prepared = script(Map.of(), "prepare", home, demo);
        assertEquals(prepared.output, 0, prepared.exit);
        assertEquals("prepare writes nothing into the user's etc/ or var/", before, snapshot(home));

        try (PlatformProcess p = Platforms.start(home, logs, "--home", demo.resolve("home").toString(),
                "--var", demo.resolve("var").toString())) {
            RestartRestoresEverythingTest.await(p, () -> String.join("\n", p.command("tinysep:drivers")),
                    s -> s.contains("TimeController") && s.contains("BusRadioAmicaUdp") && s.contains("BusRadioSunSpot"),
                    "the demo platform's drivers");
            String time = String.join("\n", p.command("tinysep:time"));
            assertTrue(time, time.contains("mode       EXTERNAL") && time.contains("sync port  " + sync)
                    && time.contains(demo.resolve("var/sync.key").toString()));
            assertTrue("a local user without the key cannot drive the clock",
                    udp(sync, "TICK 1 2030-01-01T00:00:00Z").startsWith("ERROR 1 unauthorized "));

            assertTrue("the demo's clock stays on the demo day unless released",
                    Files.readString(demo.resolve("home/etc/org.tinysep.timecontroller.cfg")).contains("syncTimeout=0"));
            // TINYSEP_DEMO_RELEASE=1: BYE at the end (without it the clock is held on the demo day: DemoDayIT)
            Result simulated = script(Map.of("TINYSEP_DEMO_DELAY", "0", "TINYSEP_DEMO_FROM", "06:00",
                    "TINYSEP_DEMO_UNTIL", "06:03", "TINYSEP_DEMO_RELEASE", "1"), "simulate", home, demo);
            assertEquals(simulated.output, 0, simulated.exit);
            assertTrue(simulated.output, simulated.output.contains("BYE"));
            time = String.join("\n", p.command("tinysep:time"));
            assertTrue("after the simulated span the clock follows real time again:\n" + time,
                    time.contains("mode       REAL"));
            assertEquals("clean stop", 0, p.stop(Duration.ofSeconds(60)));
        }
        assertEquals("the demo wrote nothing into the user's etc/ or var/", before, snapshot(home));

        try (PlatformProcess p = Platforms.start(home, logs)) { // the user's own installation (TINYSEP_DEMO=0)
            RestartRestoresEverythingTest.await(p, () -> String.join("\n", p.command("tinysep:time")),
                    s -> s.contains("mode "), "the Time Controller");
            String time = String.join("\n", p.command("tinysep:time"));
            assertTrue(time, time.contains("mode       REAL"));
            assertEquals("clean stop", 0, p.stop(Duration.ofSeconds(60)));
        }
    }

    /** @return relative path -> content of every file in {@code home}'s etc/ and var/ */
    private static Map<String, String> snapshot(Path home) throws IOException {
        Map<String, String> files = new TreeMap<>();
        for (String folder : List.of("etc", "var")) {
            try (Stream<Path> walk = Files.walk(home.resolve(folder))) {
                for (Path f : walk.filter(Files::isRegularFile).toList()) {
                    files.put(home.relativize(f).toString(), Files.readString(f, StandardCharsets.ISO_8859_1));
                }
            }
        }
        return files;
    }

    private record Result(int exit, String output) {
    }

    private static Result script(Map<String, String> env, String command, Path... args) throws Exception {
        List<String> line = new ArrayList<>(List.of("bash", SCRIPT.toString(), command));
        for (Path a : args) {
            line.add(a.toString());
        }
        Path log = Files.createTempFile("demo-flat-" + command, ".log");
        ProcessBuilder pb = new ProcessBuilder(line).redirectErrorStream(true).redirectOutput(log.toFile());
        pb.environment().remove("TINYSEP_DEMO");
        pb.environment().putAll(env);
        Process p = pb.start();
        if (!p.waitFor(3, TimeUnit.MINUTES)) {
            p.destroyForcibly().waitFor();
            throw new AssertionError("demo-flat.sh " + command + " did not end within 3 min");
        }
        String out = Files.readString(log);
        Files.delete(log);
        System.out.println("demo-flat.sh " + command + " -> " + p.exitValue() + "\n" + out);
        return new Result(p.exitValue(), out);
    }

    /** Sends one datagram to the platform's synchroniser port as a stranger would, and returns the answer. */
    private static String udp(int port, String request) throws IOException {
        try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            s.setSoTimeout(10_000);
            byte[] b = request.getBytes(StandardCharsets.US_ASCII);
            s.send(new DatagramPacket(b, b.length, InetAddress.getLoopbackAddress(), port));
            DatagramPacket in = new DatagramPacket(new byte[512], 512);
            s.receive(in);
            return new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
        }
    }
}
