package org.tinysep.itests.backup;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.net.DatagramSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * The real TinySEP distribution ({@code runtime/org.tinysep.launcher/target/tinysep}, system property
 * {@code tinysep.dist}) as a separate {@code java -jar tinysep.jar} process with the interactive Gogo shell on its
 * stdin: commands are written to stdin and their output read from stdout up to an {@code echo} marker. Its log
 * (stderr) goes to {@code <home>/platform-<n>.log}.
 */
final class PlatformProcess implements AutoCloseable {

    static final Duration COMMAND_TIMEOUT = Duration.ofSeconds(30);
    private static int launches;

    private final Process process;
    private final OutputStream stdin;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
    private int marker;

    private PlatformProcess(Process process) {
        this.process = process;
        this.stdin = process.getOutputStream();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) {
                    lines.add(line);
                }
            } catch (IOException ignored) {
                // the process ended
            }
            lines.add("\u0000EOF");
        }, "platform-stdout");
        reader.setDaemon(true);
        reader.start();
    }

    /** @return the distribution folder to copy */
    static Path distribution() {
        Path dist = Path.of(System.getProperty("tinysep.dist", "../runtime/org.tinysep.launcher/target/tinysep"));
        if (!Files.isRegularFile(dist.resolve("tinysep.jar"))) {
            throw new IllegalStateException("no distribution at " + dist.toAbsolutePath() + " (build the launcher)");
        }
        return dist;
    }

    /** Copies the distribution (without var/) to {@code home}. */
    static void install(Path home) throws IOException {
        Path from = distribution();
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : files.filter(p -> !from.relativize(p).startsWith("var")).toList()) {
                Path target = home.resolve(from.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(f, target, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
    }

    /** @return a UDP port free right now on 127.0.0.1 */
    static int freeUdpPort() {
        try (DatagramSocket s = new DatagramSocket(0, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Starts the platform in {@code home} and waits until its shell answers. */
    static PlatformProcess start(Path home) throws IOException {
        return start(home, home);
    }

    /**
     * Starts {@code home}'s tinysep.jar with {@code launcherArgs} (e.g. {@code --home}, {@code --var}); its log goes
     * to {@code logDir}.
     */
    static PlatformProcess start(Path home, Path logDir, String... launcherArgs) throws IOException {
        Path log = logDir.resolve("platform-" + (++launches) + ".log");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-XX:TieredStopAtLevel=1", "-Dorg.slf4j.simpleLogger.defaultLogLevel=info", "-jar",
                "tinysep.jar"));
        command.addAll(List.of(launcherArgs));
        Process p = new ProcessBuilder(command)
                .directory(home.toFile()).redirectError(ProcessBuilder.Redirect.appendTo(log.toFile())).start();
        PlatformProcess platform = new PlatformProcess(p);
        platform.command("echo ready", Duration.ofSeconds(60));
        return platform;
    }

    /**
     * Runs one shell command and returns its output lines (prompts removed).
     *
     * @throws IllegalStateException when no answer comes within the timeout or the process ended
     */
    List<String> command(String commandLine, Duration timeout) {
        String end = "@@END-" + (++marker) + "@@";
        try {
            stdin.write((commandLine + "\necho " + end + "\n").getBytes(StandardCharsets.UTF_8));
            stdin.flush();
        } catch (IOException e) {
            throw new IllegalStateException("platform stdin closed: " + e.getMessage(), e);
        }
        List<String> out = new ArrayList<>();
        long deadline = System.nanoTime() + timeout.toNanos();
        try {
            while (true) {
                String line = lines.poll(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                if (line == null) {
                    throw new IllegalStateException("no answer to '" + commandLine + "' within " + timeout
                            + "; so far: " + out);
                }
                if (line.equals("\u0000EOF")) {
                    lines.add(line);
                    throw new IllegalStateException("platform ended during '" + commandLine + "': " + out);
                }
                String clean = line.replace("g! ", "");
                if (clean.contains(end)) {
                    return out;
                }
                if (!clean.isBlank()) {
                    out.add(clean);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }

    List<String> command(String commandLine) {
        return command(commandLine, COMMAND_TIMEOUT);
    }

    /** Ends the shell's input: the framework stops cleanly; waits for the process to exit. */
    int stop(Duration timeout) throws InterruptedException {
        try {
            stdin.close();
        } catch (IOException ignored) {
            // already closed
        }
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            process.destroyForcibly().waitFor();
            throw new IllegalStateException("the platform did not stop within " + timeout);
        }
        return process.exitValue();
    }

    /** SIGKILL: no shutdown hook, no flush. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor();
    }

    boolean alive() {
        return process.isAlive();
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            kill();
        }
    }
}
