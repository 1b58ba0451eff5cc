package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * A command line run by {@code bash -c} as a user types it, in a given folder: its output (stdout and stderr) is
 * collected as it comes, lines can be typed into its input, and it can be waited for.
 */
final class ShellProcess implements AutoCloseable {

    private final Process process;
    private final StringBuffer output = new StringBuffer();
    private final ExecutorService reader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "shell-process-output");
        t.setDaemon(true);
        return t;
    });
    private final OutputStream input;

    ShellProcess(String commandLine, Path dir, Map<String, String> env) throws IOException {
        ProcessBuilder pb = new ProcessBuilder("bash", "-c", commandLine).directory(dir.toFile())
                .redirectErrorStream(true);
        pb.environment().remove("TINYSEP_DAEMON");
        pb.environment().putAll(env);
        process = pb.start();
        input = process.getOutputStream();
        reader.execute(() -> {
            byte[] buffer = new byte[8192];
            try (InputStream in = process.getInputStream()) {
                for (int n; (n = in.read(buffer)) > 0; ) {
                    output.append(new String(buffer, 0, n, StandardCharsets.UTF_8));
                }
            } catch (IOException e) {
                output.append("\n(output closed: ").append(e.getMessage()).append(")\n");
            }
        });
    }

    /** Runs {@code commandLine} to its end. */
    static Result run(String commandLine, Path dir, Duration timeout) throws Exception {
        try (ShellProcess p = new ShellProcess(commandLine, dir, Map.of())) {
            int rc = p.waitFor(timeout);
            return new Result(rc, p.output());
        }
    }

    record Result(int exitCode, String output) {
    }

    String output() {
        return output.toString();
    }

    int length() {
        return output.length();
    }

    /** Types one line (as Enter would end it). */
    void type(String line) throws IOException {
        input.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        input.flush();
    }

    /** Ends the input, as Ctrl-D at the start of a line does. */
    void endInput() throws IOException {
        input.close();
    }

    /** Sends SIGTERM, as {@code kill <pid>} does. */
    void terminate() {
        process.toHandle().destroy(); // Process.destroy() would also close the output before it is read
    }

    /** Waits until {@code condition} holds for the output from {@code from} on; fails with the output if not. */
    String await(int from, Predicate<String> condition, Duration timeout, String what) {
        long deadline = System.nanoTime() + timeout.toNanos();
        long endedAt = 0;
        while (true) {
            String since = output.substring(Math.min(from, output.length()));
            if (condition.test(since)) {
                return since;
            }
            if (!process.isAlive()) { // its last output may still be on the way
                endedAt = endedAt == 0 ? System.nanoTime() : endedAt;
                if (System.nanoTime() - endedAt > Duration.ofSeconds(3).toNanos()) {
                    fail("the process ended before " + what + "; output:\n" + output);
                }
            }
            if (System.nanoTime() > deadline) {
                fail("waited " + timeout.toSeconds() + " s for " + what + "; output:\n" + output);
            }
            sleep();
        }
    }

    /** @return the exit code; fails when it did not end within {@code timeout} */
    int waitFor(Duration timeout) throws InterruptedException {
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            fail("still running after " + timeout.toSeconds() + " s; output:\n" + output);
        }
        reader.shutdown();
        reader.awaitTermination(10, TimeUnit.SECONDS);
        return process.exitValue();
    }

    @Override
    public void close() {
        if (process.isAlive()) {
            process.descendants().forEach(ProcessHandle::destroyForcibly);
            process.destroyForcibly();
        }
        reader.shutdownNow();
    }

    private static void sleep() {
        try {
            Thread.sleep(100);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail("interrupted");
        }
    }
}
