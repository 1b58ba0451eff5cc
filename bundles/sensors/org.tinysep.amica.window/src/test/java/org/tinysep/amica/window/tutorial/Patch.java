package org.tinysep.amica.window.tutorial;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A diff as the tutorial writes it: {@code --- a/<path>}, {@code +++ b/<path>}, then hunks separated by lines
 * starting with {@code @@}; hunk lines start with a space (context), {@code -} (removed) or {@code +} (added).
 * Line numbers are not used: each hunk's context and removed lines must occur exactly once in the file.
 */
final class Patch {

    private record Hunk(List<String> before, List<String> after) {
    }

    private final String path;
    private final List<Hunk> hunks = new ArrayList<>();

    Patch(String diff) {
        List<String> lines = Arrays.asList(diff.split("\n", -1));
        if (lines.size() < 3 || !lines.get(0).startsWith("--- a/") || !lines.get(1).startsWith("+++ b/")
                || !lines.get(0).substring(6).equals(lines.get(1).substring(6))) {
            throw new IllegalArgumentException("a diff starts with '--- a/<path>' and '+++ b/<path>' of the same path");
        }
        path = lines.get(0).substring(6).strip();
        Hunk current = null;
        for (String l : lines.subList(2, lines.size())) {
            if (l.startsWith("@@")) {
                current = new Hunk(new ArrayList<>(), new ArrayList<>());
                hunks.add(current);
            } else if (current == null) {
                throw new IllegalArgumentException(path + ": text before the first @@: " + l);
            } else if (l.startsWith("-")) {
                current.before.add(l.substring(1));
            } else if (l.startsWith("+")) {
                current.after.add(l.substring(1));
            } else if (l.startsWith(" ") || l.isEmpty()) {
                String context = l.isEmpty() ? "" : l.substring(1);
                current.before.add(context);
                current.after.add(context);
            } else {
                throw new IllegalArgumentException(path + ": a hunk line starts with ' ', '-' or '+': " + l);
            }
        }
        while (!hunks.isEmpty()) { // a trailing empty line of the block is not context
            Hunk last = hunks.get(hunks.size() - 1);
            if (last.before.isEmpty() || !last.before.get(last.before.size() - 1).isEmpty()) {
                break;
            }
            last.before.remove(last.before.size() - 1);
            last.after.remove(last.after.size() - 1);
        }
        if (hunks.isEmpty()) {
            throw new IllegalArgumentException(path + ": no hunk");
        }
    }

    /** @return the repository path the diff applies to */
    String path() {
        return path;
    }

    /**
     * @return {@code text} with every hunk applied
     * @throws IllegalStateException naming the hunk that does not match exactly once
     */
    String apply(String text) {
        List<String> lines = new ArrayList<>(Arrays.asList(text.split("\n", -1)));
        for (Hunk h : hunks) {
            int at = -1;
            for (int i = 0; i + h.before.size() <= lines.size(); i++) {
                if (lines.subList(i, i + h.before.size()).equals(h.before)) {
                    if (at >= 0) {
                        throw new IllegalStateException(path + ": hunk matches more than once:\n" + join(h.before));
                    }
                    at = i;
                }
            }
            if (at < 0) {
                throw new IllegalStateException(path + ": hunk no longer matches the file:\n" + join(h.before));
            }
            lines.subList(at, at + h.before.size()).clear();
            lines.addAll(at, h.after);
        }
        return String.join("\n", lines);
    }

    private static String join(List<String> lines) {
        return String.join("\n", lines);
    }
}
