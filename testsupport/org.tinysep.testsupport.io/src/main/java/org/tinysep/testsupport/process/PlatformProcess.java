package org.tinysep.testsupport.process;

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
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * A TinySEP distribution run as its own {@code java -jar tinysep.jar} process, as a user runs it (so a test can
 * also kill it with SIGKILL): shell commands go to its stdin, their output is read from stdout up to an
 * {@code echo} marker; its log (stderr) goes to {@code <logDir>/platform-<n>.log}. Written once for the launcher's
 * process tests, the integration tests' backup tests and the benchmarks ({@link #attach}).
 */
public final class PlatformProcess implements AutoCloseable {

    /** How long {@link #command(String)} waits for an answer. */
    public static final Duration COMMAND_TIMEOUT = Duration.ofSeconds(30);
    private static final String EOF = "\u0000EOF";
    private static int launches;

    private final Process process;
    private final OutputStream stdin;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
    private int marker;

    private PlatformProcess(Process process, Consumer<String> eachLine) {
        this.process = process;
        this.stdin = process.getOutputStream();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) {
                    eachLine.accept(line);
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

    /** Starts the distribution in {@code home} (log there too) and waits until its shell answers. */
    public static PlatformProcess start(Path home) throws IOException {
        return start(home, home, List.of());
    }

    /** Starts {@code java <jvmOptions> -jar tinysep.jar <args>} in {@code home}; waits until its shell answers. */
    public static PlatformProcess start(Path home, Path logDir, List<String> jvmOptions, String... args)
            throws IOException {
        PlatformProcess platform = launch(home, logDir, jvmOptions, args);
        platform.command("echo ready", Duration.ofSeconds(90));
        return platform;
    }

    /** Starts {@code java <jvmOptions> -jar tinysep.jar <args>} in {@code home} and returns at once. */
    public static PlatformProcess launch(Path home, Path logDir, List<String> jvmOptions, String... args)
            throws IOException {
        Path log = logDir.resolve("platform-" + nextLaunch() + ".log");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-XX:TieredStopAtLevel=1"));
        command.addAll(jvmOptions);
        command.addAll(List.of("-jar", "tinysep.jar"));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).directory(home.toFile())
                .redirectError(ProcessBuilder.Redirect.appendTo(log.toFile()));
        builder.environment().remove("TINYSEP_DAEMON"); // the shell on stdin, whatever the test's environment says
        return new PlatformProcess(builder.start(), line -> { });
    }

    /**
     * Talks to a distribution process started elsewhere (the benchmarks start it with their own JVM options and
     * environment): its shell through stdin/stdout as above; {@code eachLine} sees every stdout line first, on the
     * reader thread (e.g. to time the start banner). Returns at once.
     */
    public static PlatformProcess attach(Process process, Consumer<String> eachLine) {
        return new PlatformProcess(process, eachLine);
    }

    private static synchronized int nextLaunch() {
        return ++launches;
    }

    /**
     * Runs one shell command; @return its output lines (prompts removed).
     *
     * @throws IllegalStateException when no answer comes within the timeout or the process ended
     */
    public List<String> command(String commandLine, Duration timeout) {
        String end = "@@END-" + (++marker) + "@@";
        try {
            stdin.write((commandLine + "\necho " + end + "\n").getBytes(StandardCharsets.UTF_8));
            stdin.flush();
        } catch (IOException e) {
            throw new IllegalStateException("platform stdin closed: " + e.getMessage(), e);
        }
        List<String> out = new ArrayList<>();
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            String line = next(deadline, () -> "no answer to '" + commandLine + "' within " + timeout + ": " + out,
                    () -> "platform ended during '" + commandLine + "': " + out);
            String clean = line.replace("g! ", "");
            if (clean.contains(end)) {
                return out;
            }
            if (!clean.isBlank()) {
                out.add(clean);
            }
        }
    }

    /** {@link #command(String, Duration)} with {@link #COMMAND_TIMEOUT}. */
    public List<String> command(String commandLine) {
        return command(commandLine, COMMAND_TIMEOUT);
    }

    /** @return {@link #command(String)}'s lines joined with newlines */
    public String text(String commandLine) {
        return String.join("\n", command(commandLine));
    }

    /** Waits for a stdout line containing {@code text} (earlier lines are consumed); @return that line */
    public String awaitLine(String text, Duration timeout) {
        List<String> seen = new ArrayList<>();
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            String line = next(deadline, () -> "no line with '" + text + "' within " + timeout + ": " + seen,
                    () -> "no line with '" + text + "' (the platform ended): " + seen);
            if (line.contains(text)) {
                return line;
            }
            seen.add(line);
        }
    }

    /** @return the next stdout line, waiting until {@code deadline} ({@link System#nanoTime()}) */
    private String next(long deadline, Supplier<String> late, Supplier<String> ended) {
        try {
            String line = lines.poll(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            if (line == null) {
                throw new IllegalStateException(late.get());
            }
            if (line.equals(EOF)) {
                lines.add(line);
                throw new IllegalStateException(ended.get());
            }
            return line;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }

    /** @return the operating system's process id */
    public long pid() {
        return process.pid();
    }

    public Process process() {
        return process;
    }

    public boolean alive() {
        return process.isAlive();
    }

    /**
     * Ends the shell's input: the framework stops cleanly; waits for the process to exit. @return its exit value
     *
     * @throws IllegalStateException if it did not stop in time (it is then killed)
     */
    public int stop(Duration timeout) throws InterruptedException {
        try {
            stdin.close();
        } catch (IOException ignored) {
            // already closed
        }
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            kill();
            throw new IllegalStateException("the platform did not stop within " + timeout);
        }
        return process.exitValue();
    }

    /** SIGKILL: no shutdown hook, nothing flushed, nothing saved. */
    public void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor();
    }

    /** Stops the platform cleanly if it still runs (killed if that takes over 30 s). */
    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            try {
                stop(Duration.ofSeconds(30));
            } catch (IllegalStateException late) {
                // killed: a test that needs to know calls stop() itself
            }
        }
    }
}
