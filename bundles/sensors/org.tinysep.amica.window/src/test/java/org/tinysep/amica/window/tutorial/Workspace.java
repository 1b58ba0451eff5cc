package org.tinysep.amica.window.tutorial;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * A scratch copy of the repository in which the tutorial has been followed: the sibling bundle copied, the copy
 * script run, every complete file written and every diff applied to a copy of the current repository file.
 */
final class Workspace {

    static final String SIBLING = "bundles/sensors/org.tinysep.amica.window";
    private static final String JAVA_FILE = "// File: ";
    private static final String MARKDOWN_FILE = "<!-- File: ";

    final Path repo;
    final Path root;
    final Markdown page;
    /** Repository paths of the complete files the tutorial gives, in page order. */
    final List<String> files = new ArrayList<>();
    /** Repository paths the tutorial's diffs changed, in page order. */
    final List<String> patched = new ArrayList<>();

    private Workspace(Path repo, Path root, Markdown page) {
        this.repo = repo;
        this.root = root;
        this.page = page;
    }

    static Workspace follow(Path repo, Path root, String tutorial) throws IOException, InterruptedException {
        Workspace w = new Workspace(repo, root, new Markdown(Files.readString(repo.resolve(tutorial))));
        w.copyTree(repo.resolve(SIBLING), root.resolve(SIBLING));
        for (Markdown.Block b : w.page.blocks()) {
            if (b.language().equals("sh") && b.has("copy")) {
                w.run(b);
            }
        }
        for (Markdown.Block b : w.page.blocks()) {
            if (b.language().equals("java") || b.language().equals("markdown")) {
                w.write(b);
            } else if (b.language().equals("diff")) {
                w.patch(b);
            }
        }
        return w;
    }

    /** @return the scratch copy of a repository path */
    Path file(String repoPath) {
        return root.resolve(repoPath);
    }

    private void run(Markdown.Block b) throws IOException, InterruptedException {
        Process p = new ProcessBuilder("bash", "-e", "-u", "-c", b.body()).directory(root.toFile())
                .redirectErrorStream(true).start();
        if (!p.waitFor(60, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("the copy script of line " + b.line() + " did not finish in 60 s");
        }
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.exitValue() != 0) {
            throw new AssertionError("the copy script of line " + b.line() + " failed (exit " + p.exitValue()
                    + "):\n" + output);
        }
    }

    private void write(Markdown.Block b) throws IOException {
        String body = b.body();
        String first = body.lines().findFirst().orElse("");
        String path;
        if (first.startsWith(JAVA_FILE)) {
            path = first.substring(JAVA_FILE.length()).strip();
        } else if (first.startsWith(MARKDOWN_FILE) && first.endsWith("-->")) {
            path = first.substring(MARKDOWN_FILE.length(), first.length() - 3).strip();
        } else if (b.language().equals("java")) {
            throw new AssertionError("the Java block of line " + b.line() + " does not start with '" + JAVA_FILE
                    + "<repository path>'");
        } else {
            return; // a Markdown example that is not a file
        }
        Path target = file(path);
        Files.createDirectories(target.getParent());
        Files.writeString(target, body.substring(first.length() + 1));
        files.add(path);
    }

    private void patch(Markdown.Block b) throws IOException {
        Patch p;
        try {
            p = new Patch(b.body());
        } catch (IllegalArgumentException e) {
            throw new AssertionError("the diff of line " + b.line() + ": " + e.getMessage());
        }
        Path target = file(p.path());
        if (!Files.exists(target)) {
            Path original = repo.resolve(p.path());
            if (!Files.isRegularFile(original)) {
                throw new AssertionError("the diff of line " + b.line() + " patches " + p.path()
                        + ", which neither exists nor was made by an earlier step");
            }
            Files.createDirectories(target.getParent());
            Files.copy(original, target);
        }
        try {
            Files.writeString(target, p.apply(Files.readString(target)));
        } catch (IllegalStateException e) {
            throw new AssertionError("the diff of line " + b.line() + ": " + e.getMessage());
        }
        patched.add(p.path());
    }

    private void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> all = Files.walk(from)) {
            for (Path f : all.filter(Files::isRegularFile).toList()) {
                Path rel = from.relativize(f);
                if (rel.startsWith("target")) {
                    continue;
                }
                Files.createDirectories(to.resolve(rel).getParent());
                Files.copy(f, to.resolve(rel));
            }
        }
    }
}
