package org.tinysep.tools.process;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * The conversation with the platform's Gogo shell: a command goes to its standard input followed by {@code echo
 * <marker>}, and its answer is every standard output line up to the marker. Lines nobody reads are kept up to a
 * bound (a daemon's output, a long run), the oldest dropped first.
 */
final class ShellLines {

    static final Duration COMMAND_TIMEOUT = Duration.ofSeconds(30);
    private static final int KEPT = 10_000;
    private static final String EOF = "\u0000EOF";

    private final OutputStream stdin;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
    private int marker;

    ShellLines(OutputStream stdin) {
        this.stdin = stdin;
    }

    void add(String line) {
        while (lines.size() >= KEPT) {
            lines.poll();
        }
        lines.add(line);
    }

    void end() {
        lines.add(EOF);
    }

    void closeInput() {
        try {
            stdin.close();
        } catch (IOException ignored) {
            // already closed
        }
    }

    synchronized List<String> command(String commandLine, Duration timeout) {
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

    synchronized String awaitLine(String text, Duration timeout) {
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

    /** @return the next line, waiting until {@code deadline} ({@link System#nanoTime()}) */
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
}
