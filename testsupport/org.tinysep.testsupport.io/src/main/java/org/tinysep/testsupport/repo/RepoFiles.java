package org.tinysep.testsupport.repo;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Files of the repository for tests: the root is found by walking up from the working directory (Maven runs each
 * module's tests in the module's folder) to the parent pom, the one {@code pom.xml} that declares
 * {@code tinysep-parent} without a {@code <parent>}. A path given here is resolved against that root and refused
 * when it leaves it, by {@code ..} or by a symbolic link: a test can read nothing beside the clone.
 */
public final class RepoFiles {

    private static final String PARENT_ARTIFACT = "<artifactId>tinysep-parent</artifactId>";

    private RepoFiles() {
    }

    /** @return the repository root (real path) above the working directory */
    public static Path root() {
        return rootAbove(Path.of("").toAbsolutePath());
    }

    /**
     * @param start a folder inside the repository
     * @return the repository root (real path) at or above {@code start}
     * @throws IllegalStateException when no folder above holds the parent pom
     */
    public static Path rootAbove(Path start) {
        for (Path dir = start.toAbsolutePath().normalize(); dir != null; dir = dir.getParent()) {
            if (isRoot(dir)) {
                return real(dir);
            }
        }
        throw new IllegalStateException("no TinySEP repository above " + start.toAbsolutePath() + ": no pom.xml "
                + "declaring tinysep-parent without a <parent>; run the tests from inside the clone");
    }

    /**
     * @param first the first name below the root, e.g. {@code "data"}
     * @param more  further names, e.g. {@code "ordonez", "OrdonezA_Sensors.txt"}
     * @return the path inside the repository (it need not exist)
     * @throws IllegalArgumentException when the path leaves the repository
     */
    public static Path resolve(String first, String... more) {
        return inside(root(), Path.of(first, more));
    }

    /**
     * @return the existing, readable file or folder inside the repository
     * @throws IllegalArgumentException when the path leaves the repository
     * @throws IllegalStateException    when it is missing, naming it and where the repository keeps its data
     */
    public static Path require(String first, String... more) {
        Path p = resolve(first, more);
        if (!Files.isReadable(p)) {
            throw new IllegalStateException(p + " is missing from the repository; the tests read only files of the "
                    + "clone (test data lives in data/, see its PROVENANCE.md files); is the checkout complete?");
        }
        return p;
    }

    /**
     * @param root     the repository root (real path)
     * @param relative a path relative to it
     * @return {@code root.resolve(relative)} normalised
     * @throws IllegalArgumentException when the result, or the real file it names, lies outside {@code root}
     */
    static Path inside(Path root, Path relative) {
        if (relative.isAbsolute()) {
            throw refused(relative, root, "is absolute");
        }
        Path p = root.resolve(relative).normalize();
        if (!p.startsWith(root)) {
            throw refused(relative, root, "leaves it");
        }
        Path existing = p;
        while (!Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (!real(existing).startsWith(root)) {
            throw refused(relative, root, "goes through a link to " + real(existing));
        }
        return p;
    }

    private static IllegalArgumentException refused(Path relative, Path root, String why) {
        return new IllegalArgumentException("refused: " + relative + " " + why + ", outside the repository " + root
                + "; tests read only files of the clone (put test data under data/ with its provenance)");
    }

    private static boolean isRoot(Path dir) {
        Path pom = dir.resolve("pom.xml");
        if (!Files.isRegularFile(pom)) {
            return false;
        }
        try {
            String text = Files.readString(pom);
            return text.contains(PARENT_ARTIFACT) && !text.contains("<parent>");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + pom, e);
        }
    }

    private static Path real(Path p) {
        try {
            return p.toRealPath();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot resolve " + p, e);
        }
    }
}
