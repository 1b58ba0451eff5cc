package org.tinysep.launcher;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A copied distribution ({@link TestDistribution}) run as its own {@code java -jar tinysep.jar} process, so it can
 * be killed with SIGKILL: shell commands go to its stdin, their output is read from stdout up to an {@code echo}
 * marker; its log (stderr) goes to {@code <home>/platform-<n>.log}.
 */
final class PlatformProcess implements AutoCloseable {

    private static final String EOF = "\u0000EOF";
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
            lines.add(EOF);
        }, "platform-stdout");
        reader.setDaemon(true);
        reader.start();
    }

    /** Starts the distribution in {@code home} with its interactive shell and waits until the shell answers. */
    static PlatformProcess start(Path home) throws IOException {
        PlatformProcess platform = launch(home);
        platform.command("echo ready", Duration.ofSeconds(90));
        return platform;
    }

    /** Starts {@code java -jar tinysep.jar <args>} in {@code home} and returns at once. */
    static PlatformProcess launch(Path home, String... args) throws IOException {
        return launch(home, List.of(), args);
    }

    /** Starts {@code java <jvmOptions> -jar tinysep.jar <args>} in {@code home} and returns at once. */
    static PlatformProcess launch(Path home, List<String> jvmOptions, String... args) throws IOException {
        Path log = home.resolve("platform-" + (++launches) + ".log");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-XX:TieredStopAtLevel=1"));
        command.addAll(jvmOptions);
        command.addAll(List.of("-jar", "tinysep.jar"));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).directory(home.toFile())
                .redirectError(ProcessBuilder.Redirect.appendTo(log.toFile()));
        builder.environment().remove(Options.DAEMON_ENV);
        return new PlatformProcess(builder.start());
    }

    /** Waits for a stdout line containing {@code text} (earlier lines are consumed); @return that line */
    String awaitLine(String text, Duration timeout) {
        long deadline = System.nanoTime() + timeout.toNanos();
        List<String> seen = new ArrayList<>();
        try {
            while (true) {
                String line = lines.poll(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                if (line == null || line.equals(EOF)) {
                    if (line != null) {
                        lines.add(line);
                    }
                    throw new IllegalStateException("no line with '" + text + "' within " + timeout
                            + (line == null ? "" : " (the platform ended)") + ": " + seen);
                }
                if (line.contains(text)) {
                    return line;
                }
                seen.add(line);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }

    /** @return the operating system's process id */
    long pid() {
        return process.pid();
    }

    Process process() {
        return process;
    }

    /** Runs one shell command; @return its output lines (prompts removed) */
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
                    throw new IllegalStateException("no answer to '" + commandLine + "' within " + timeout + ": "
                            + out);
                }
                if (line.equals(EOF)) {
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

    String command(String commandLine) {
        return String.join("\n", command(commandLine, Duration.ofSeconds(30)));
    }

    /** SIGKILL: no shutdown hook, nothing flushed, nothing saved. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor();
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            try {
                stdin.close(); // the shell ends: the framework stops cleanly
            } catch (IOException ignored) {
                // already closed
            }
            if (!process.waitFor(30, TimeUnit.SECONDS)) {
                kill();
            }
        }
    }
}
