package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Does what README.md's "Try it in one minute" and the new-sensor tutorial's last step say, as written: in a
 * scratch checkout (this distribution, {@code run.sh}, {@code scripts/demo-flat.sh}) it runs {@code ./run.sh}
 * (no build, no demo, its own state folder), types the README's shell commands into the real Gogo shell and
 * compares their answers with the README's transcript, runs the sender commands from the repository root, and
 * stops TinySEP in every way the README names. The README's text drives the test: change one and the other must
 * follow. The scratch copy's bus radio listens on a free port (the sender reads it from {@code etc/}, as it
 * does from the port the README states), so the test never collides with a running TinySEP.
 */
class ReadmeWalkIT {

    private static final Duration START = Duration.ofSeconds(180);
    private static final Duration ANSWER = Duration.ofSeconds(60);
    private static final String PROMPT = "g! ";
    private static final Path REPO = Path.of("").toAbsolutePath().resolve("../..").normalize();
    private static final Path README = REPO.resolve("README.md");
    private static final Path TUTORIAL = REPO.resolve("docs/tutorial-new-sensor.md");

    @TempDir
    static Path root;
    private static int runs;

    @BeforeAll
    static void scratchCheckout() throws Exception {
        Path dist = root.resolve("runtime/org.tinysep.launcher/target/tinysep");
        new TestDistribution(dist, null); // a copy of target/tinysep
        try (var shipped = Files.list(Path.of("src/main/dist/etc"))) { // etc/ as shipped (no demo leftovers)
            for (Path f : Files.list(dist.resolve("etc")).toList()) {
                Files.delete(f);
            }
            for (Path f : shipped.toList()) {
                Files.copy(f, dist.resolve("etc").resolve(f.getFileName()));
            }
        }
        String shippedPort = property(dist.resolve("etc/" + TestDistribution.UDP_PID + ".cfg"), "port");
        assertTrue(Files.readString(README).contains("`127.0.0.1:" + shippedPort + "`"),
                "the README states the bus radio's shipped port " + shippedPort);
        Files.writeString(dist.resolve("etc/" + TestDistribution.UDP_PID + ".cfg"),
                "port=" + freePort() + "\nbindAddress=127.0.0.1\n");
        Files.writeString(dist.resolve("etc/org.tinysep.sunspot.busradio.cfg"), "udpPort=0\nudpBindAddress=127.0.0.1\n");
        Files.writeString(dist.resolve("etc/org.tinysep.timecontroller.cfg"), "syncPort=0\n");
        Files.copy(REPO.resolve("run.sh"), root.resolve("run.sh"));
        Files.createDirectories(root.resolve("scripts"));
        Files.copy(REPO.resolve("scripts/demo-flat.sh"), root.resolve("scripts/demo-flat.sh"));
    }

    @Test
    void tryItInOneMinuteWorksAsWritten() throws Exception {
        MarkdownBlocks tryIt = MarkdownBlocks.section(README, "## Try it in one minute");
        List<MarkdownBlocks.Block> blocks = tryIt.blocks();
        assertEquals(List.of("./run.sh"), blocks.get(0).commands(), "the walk starts with ./run.sh");
        try (ShellProcess tinysep = start("./run.sh")) {
            String console = tinysep.await(0, s -> s.contains(PROMPT), START, "the shell prompt");
            System.out.println("=== the console of a first start ===\n" + console);
            Matcher banner = Pattern.compile("(\\d+/\\d+ bundles active)").matcher(tryIt.text());
            assertTrue(banner.find(), "the README quotes the banner");
            assertTrue(console.contains(banner.group(1)), "banner as the README says: " + banner.group(1));
            assertQuiet(console);
            for (MarkdownBlocks.Block block : blocks.subList(1, blocks.size())) {
                if (block.info().equals("sh")) {
                    block.commands().forEach(ReadmeWalkIT::send);
                } else {
                    transcript(tinysep, block.lines());
                }
            }
            tutorialSender();
            answers(tinysep, "tinysep:set", "usage: tinysep:set <uid> <key> <value>");
            answers(tinysep, "tinysep:events --device nosuch", "no device matches 'nosuch'");
            tinysep.endInput(); // Ctrl-D, the first way the README names
            assertEquals(0, tinysep.waitFor(Duration.ofSeconds(60)), "exit code after Ctrl-D");
        }
    }

    @Test
    void everyWayToStopThatTheReadmeNamesStopsCleanly() throws Exception {
        List<String> ways = MarkdownBlocks.section(README, "## Try it in one minute")
                .codeSpansOfParagraph("**Stop it**");
        assertTrue(ways.containsAll(List.of("exit", "stop 0", "./run.sh --daemon")), ways.toString());
        for (String command : List.of("exit", "stop 0")) {
            try (ShellProcess tinysep = start("./run.sh")) {
                tinysep.await(0, s -> s.contains(PROMPT), START, "the shell prompt");
                tinysep.type(command);
                assertEquals(0, tinysep.waitFor(Duration.ofSeconds(60)), "exit code after '" + command + "'");
                assertFalse(tinysep.output().contains("Cannot coerce"), tinysep.output());
            }
        }
        try (ShellProcess daemon = start("./run.sh --daemon")) {
            daemon.await(0, s -> s.contains("bundles active"), START, "the banner");
            daemon.terminate(); // SIGTERM, as kill <pid> sends
            daemon.waitFor(Duration.ofSeconds(60));
            assertTrue(daemon.output().contains("Stopping TinySEP"), daemon.output());
        }
    }

    /** Each "g! command" of a transcript block, answered as the lines below it show (retried while the node's packets arrive). */
    private static void transcript(ShellProcess tinysep, List<String> lines) throws Exception {
        for (int i = 0; i < lines.size(); i++) {
            if (!lines.get(i).startsWith(PROMPT)) {
                continue;
            }
            List<String> expected = new ArrayList<>();
            for (int j = i + 1; j < lines.size() && !lines.get(j).startsWith(PROMPT); j++) {
                expected.add(lines.get(j));
            }
            String command = lines.get(i).substring(PROMPT.length());
            long deadline = System.nanoTime() + ANSWER.toNanos();
            String answer = ask(tinysep, command);
            while (!MarkdownBlocks.shows(expected, answer) && System.nanoTime() < deadline) {
                Thread.sleep(500); // the sender's datagrams are handled on the radio's thread
                answer = ask(tinysep, command);
            }
            assertTrue(MarkdownBlocks.shows(expected, answer), "'" + command + "' answers as the README shows:\n"
                    + String.join("\n", expected) + "\n--- but answered ---\n" + answer);
        }
    }

    private static void answers(ShellProcess tinysep, String command, String part) throws Exception {
        String answer = ask(tinysep, command);
        assertTrue(answer.contains(part), command + " → " + answer);
    }

    /** @return what the shell printed for {@code command} before its next prompt */
    private static String ask(ShellProcess tinysep, String command) throws Exception {
        int mark = tinysep.length();
        tinysep.type(command);
        String since = tinysep.await(mark, s -> s.contains(PROMPT), ANSWER, "the answer to " + command);
        return since.substring(0, since.indexOf(PROMPT));
    }

    /** Runs a sender command from the repository root (the scratch checkout) as written. */
    private static void send(String command) {
        try {
            Matcher node = Pattern.compile("--node (\\S+)").matcher(command);
            assertTrue(node.find(), command);
            assertFalse(demoFlatAddresses().contains(node.group(1)), "node " + node.group(1)
                    + " would replace a device of the demo flat (simulator/.../flat-a/nodes.txt): " + command);
            ShellProcess.Result r = ShellProcess.run(command, root, ANSWER);
            assertEquals(0, r.exitCode(), command + " → " + r.output());
            assertTrue(r.output().startsWith("sent "), command + " → " + r.output());
        } catch (Exception e) {
            throw new AssertionError(command, e);
        }
    }

    /**
     * The tutorial's sender command, as written. Its node type {@code water-leak} exists only once the tutorial's
     * step 1 is built, so this distribution may refuse the type, but nothing else (no missing class, no bad path).
     */
    private static void tutorialSender() throws Exception {
        List<String> commands = MarkdownBlocks.section(TUTORIAL, "## Step 10: build and try it").blocks().stream()
                .flatMap(b -> b.commands().stream()).filter(c -> c.contains("amica-send")).toList();
        assertEquals(1, commands.size(), commands.toString());
        ShellProcess.Result r = ShellProcess.run(commands.get(0), root, ANSWER);
        assertTrue(r.exitCode() == 0 && r.output().startsWith("sent ") || r.exitCode() == 2
                && r.output().startsWith("amica-send: unknown node type 'water-leak'"), commands.get(0) + " → " + r);
    }

    /** No SPI Fly or JAXB chatter, no list dumps, no line per placed device (issue 17 item 8). */
    private static void assertQuiet(String console) {
        for (String line : console.lines().toList()) {
            assertFalse(line.contains("spifly") || line.contains("Registered provider"), line);
            assertFalse(line.contains("Placed device"), line);
            assertTrue(line.length() <= 300, "one screen line, not a dump: " + line);
        }
    }

    private static ShellProcess start(String command) throws Exception {
        return new ShellProcess(command, root, Map.of("SKIP_BUILD", "1", "TINYSEP_DEMO", "0",
                "TINYSEP_VAR", root.resolve("var-" + ++runs).toString()));
    }

    private static List<String> demoFlatAddresses() throws Exception {
        return Files.readAllLines(REPO.resolve("simulator/src/main/resources/flats/flat-a/nodes.txt")).stream()
                .filter(l -> !l.startsWith("#") && l.contains("|")).map(l -> l.split("\\|")[2].strip()).toList();
    }

    private static String property(Path cfg, String key) throws Exception {
        return Files.readAllLines(cfg).stream().filter(l -> l.startsWith(key + "="))
                .map(l -> l.substring(key.length() + 1).strip()).findFirst().orElseThrow();
    }

    private static int freePort() throws Exception {
        try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }
}
