package org.tinysep.tools.process;

import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.InterruptedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/**
 * A TinySEP distribution run as its own {@code java -jar tinysep.jar} process, as a user runs it (so a test can also
 * kill it with SIGKILL). {@link #in(Path)} says how to start it; then {@link #banner()} holds the start banner's
 * figures, shell commands go to its standard input and their output is read up to an {@code echo} marker ({@link
 * ShellLines}), and {@link #stop(Duration)} ends it in order (end of input, or SIGTERM for a daemon), killing it when
 * that takes too long. Every child is reaped, and killed if still running when this JVM exits ({@link
 * ChildProcesses}).
 */
public final class PlatformProcess implements AutoCloseable {

    /** How long {@link #command(String)} waits for an answer. */
    public static final Duration COMMAND_TIMEOUT = ShellLines.COMMAND_TIMEOUT;
    private static int launches;

    private final Process process;
    private final PlatformLaunch launch;
    private final long startNanos;
    private final OutputTail tail = new OutputTail();
    private final ShellLines shell;
    private final CountDownLatch bannerOrEnd = new CountDownLatch(1);
    private volatile Banner banner;
    private long stopNanos;

    PlatformProcess(Process process, PlatformLaunch launch, long startNanos) {
        this.process = process;
        this.launch = launch;
        this.startNanos = startNanos;
        this.shell = new ShellLines(process.getOutputStream());
        Thread reader = new Thread(this::read, "platform-stdout-" + process.pid());
        reader.setDaemon(true);
        reader.start();
    }

    /** @return how to start the distribution whose home (working folder) is {@code home} */
    public static PlatformLaunch in(Path home) {
        return new PlatformLaunch(home);
    }

    /** Starts the distribution in {@code home} (log there too) and waits until its shell answers. */
    public static PlatformProcess start(Path home) throws IOException {
        return start(home, home, List.of());
    }

    /**
     * Starts {@code java -XX:TieredStopAtLevel=1 <jvmOptions> -jar tinysep.jar <args>} in {@code home}, its log in
     * {@code <logDir>/platform-<n>.log}; waits for the banner and the shell's answer.
     */
    public static PlatformProcess start(Path home, Path logDir, List<String> jvmOptions, String... args)
            throws IOException {
        return testLaunch(home, logDir, jvmOptions, args).start();
    }

    /** As {@link #start(Path, Path, List, String...)} but returns at once. */
    public static PlatformProcess launch(Path home, Path logDir, List<String> jvmOptions, String... args)
            throws IOException {
        return testLaunch(home, logDir, jvmOptions, args).launch();
    }

    private static PlatformLaunch testLaunch(Path home, Path logDir, List<String> jvmOptions, String... args) {
        List<String> jvm = new ArrayList<>(List.of("-XX:TieredStopAtLevel=1"));
        jvm.addAll(jvmOptions);
        return in(home).jvm(jvm).args(args).log(logDir.resolve("platform-" + nextLaunch() + ".log"));
    }

    private static synchronized int nextLaunch() {
        return ++launches;
    }

    private void read() {
        Path copy = launch.stdoutCopyFile();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                StandardCharsets.UTF_8)); BufferedWriter w = copy == null ? null : Files.newBufferedWriter(copy)) {
            for (String line; (line = r.readLine()) != null; ) {
                tail.add(line);
                if (banner == null) {
                    banner = Banner.parse(line, msSinceStart(), process.info().totalCpuDuration().orElse(null))
                            .orElse(null);
                    if (banner != null) {
                        bannerOrEnd.countDown();
                    }
                }
                launch.lineListener().accept(line);
                if (w != null) {
                    w.write(line);
                    w.newLine();
                    w.flush();
                }
                shell.add(line);
            }
        } catch (IOException ignored) {
            // the process ended
        }
        shell.end();
        bannerOrEnd.countDown();
    }

    /** Waits for the banner and, with the shell on stdin, for its answer; kills the child and explains on failure. */
    void awaitUp(Duration timeout) throws IOException {
        long deadline = System.nanoTime() + timeout.toNanos();
        try {
            if (!bannerOrEnd.await(timeout.toNanos(), TimeUnit.NANOSECONDS)) {
                throw failure("did not print its banner within " + timeout.toSeconds() + " s");
            }
            if (banner == null) {
                process.waitFor(5, TimeUnit.SECONDS);
                throw failure("ended before its banner" + (process.isAlive() ? "" : " (exit value "
                        + process.exitValue() + ")"));
            }
            if (!launch.isDaemon()) {
                try {
                    shell.command("echo ready", Duration.ofNanos(Math.max(1, deadline - System.nanoTime())));
                } catch (IllegalStateException e) {
                    throw failure("printed its banner but its shell did not answer: " + e.getMessage());
                }
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while the platform started");
        }
    }

    /**
     * Polls {@code condition} every 50 ms until it holds (e.g. a radio's port bound after the banner).
     *
     * @throws IOException when the child ends or {@code timeout} passes first; the child is then killed
     */
    public void awaitUntil(BooleanSupplier condition, String what, Duration timeout) throws IOException {
        long deadline = System.nanoTime() + timeout.toNanos();
        try {
            while (!condition.getAsBoolean()) {
                if (!process.isAlive()) {
                    throw failure("ended before " + what);
                }
                if (System.nanoTime() > deadline) {
                    throw failure("did not reach '" + what + "' within " + timeout.toSeconds() + " s");
                }
                Thread.sleep(50);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted waiting for " + what);
        }
    }

    /** Kills the child (reaped) and @return an exception with its last output and log lines */
    private IOException failure(String what) throws InterruptedException {
        kill();
        return new IOException("the platform (" + String.join(" ", launch.command()) + ") " + what
                + tail.describe(launch.logFile()));
    }

    /** @return the start banner's figures, or null before it came */
    public Banner banner() {
        return banner;
    }

    /** @return wall time from starting the process to its banner, in ms; NaN before it came */
    public double msToBanner() {
        Banner b = banner;
        return b == null ? Double.NaN : b.msFromStart();
    }

    /** @return {@link System#nanoTime()} just before the process was started */
    public long startNanos() {
        return startNanos;
    }

    /** @return wall time since the process was started, in ms */
    public double msSinceStart() {
        return (System.nanoTime() - startNanos) / 1e6;
    }

    /** @return ms from asking for the stop to the process's end (0 before {@link #stop}) */
    public double msToStop() {
        return stopNanos / 1e6;
    }

    /** @return the last standard output lines (at most 20) */
    public List<String> lastLines() {
        return tail.lines();
    }

    /**
     * Runs one shell command; @return its output lines (prompts removed).
     *
     * @throws IllegalStateException when no answer comes within the timeout or the process ended
     */
    public List<String> command(String commandLine, Duration timeout) {
        return shell.command(commandLine, timeout);
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
        return shell.awaitLine(text, timeout);
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

    /** @return the file the child's standard error (its log) goes to */
    public Path log() {
        return launch.logFile();
    }

    /**
     * Stops the platform in order (the end of its shell's input; SIGTERM for a daemon: the framework stops cleanly)
     * and waits for the process to exit. @return its exit value
     *
     * @throws IllegalStateException if it did not stop in time: it is then killed
     */
    public int stop(Duration timeout) throws InterruptedException {
        long asked = System.nanoTime();
        if (launch.isDaemon()) {
            process.destroy();
        } else {
            shell.closeInput();
        }
        try {
            if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
                kill();
                throw new IllegalStateException("the platform did not stop within " + timeout.toSeconds()
                        + " s; killed" + tail.describe(launch.logFile()));
            }
        } catch (InterruptedException e) {
            process.destroyForcibly(); // the caller is giving up: never leave a platform behind
            throw e;
        }
        stopNanos = System.nanoTime() - asked;
        return process.exitValue();
    }

    /** SIGKILL: no shutdown hook, nothing flushed, nothing saved; waits until the process is gone. */
    public void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor();
    }

    /** Stops the platform in order if it still runs, killed after the launch's stop timeout (default 30 s). */
    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            try {
                stop(launch.closeTimeout());
            } catch (IllegalStateException late) {
                // killed: a caller that needs to know calls stop() itself
            }
        }
    }
}
