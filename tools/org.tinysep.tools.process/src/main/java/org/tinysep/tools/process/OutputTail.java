package org.tinysep.tools.process;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/** The last lines a child printed, kept to explain a failure (a start that never came, a stop that hung). */
final class OutputTail {

    static final int LINES = 20;

    private final Deque<String> lines = new ArrayDeque<>();

    synchronized void add(String line) {
        if (lines.size() == LINES) {
            lines.removeFirst();
        }
        lines.addLast(line);
    }

    synchronized List<String> lines() {
        return new ArrayList<>(lines);
    }

    /**
     * @return a paragraph for an error message: the last standard output lines and the last lines of {@code log}
     *         (the child's standard error), each indented
     */
    String describe(Path log) {
        StringBuilder b = new StringBuilder();
        List<String> out = lines();
        b.append("\n  its last output lines").append(out.isEmpty() ? ": none" : ":");
        out.forEach(l -> b.append("\n    | ").append(l));
        if (log != null) {
            List<String> err = lastLines(log);
            b.append("\n  the last lines of its log ").append(log).append(err.isEmpty() ? ": none" : ":");
            err.forEach(l -> b.append("\n    | ").append(l));
        }
        return b.toString();
    }

    private static List<String> lastLines(Path file) {
        try {
            List<String> all = Files.readAllLines(file, java.nio.charset.StandardCharsets.UTF_8);
            return all.subList(Math.max(0, all.size() - LINES), all.size());
        } catch (IOException | RuntimeException e) {
            return List.of();
        }
    }
}
