package org.tinysep.testsupport.repo;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Finds build and test inputs that reach outside the repository (issue 32): in every source, pom, bnd file, script,
 * configuration and test resource, (1) an absolute path into this machine's {@code /work}, (2) a path that climbs
 * to the sibling folder material is handed over in ({@link #HANDOVER_FOLDER}; written with slashes or as listed path
 * parts), (3) a relative path whose
 * {@code ..} steps, taken from the folder the file is read in (a module's folder: Maven's working directory and the
 * base of its pom; a script's own folder: the scripts {@code cd} there), climb above the repository root.
 */
final class OutsideReferences {

    /**
     * The allow-list: folders (relative to the root) not scanned, each with its reason. Documentation ({@code *.md})
     * is no input and is not scanned either: it may point at reference material beside a clone (e.g. the thesis);
     * nor are build output (Maven's {@code target/}, Gradle's {@code build/}), {@code node_modules/} and dot folders ({@code .git/}).
     */
    static final Map<String, String> ALLOWED = Map.of(
            "data/", "the recorded data itself (data/*/PROVENANCE.md)",
            "var/", "the state folder ./run.sh writes (git-ignored): the platform's own files, not build inputs",
            "testsupport/org.tinysep.testsupport.io/src/test/java/org/tinysep/testsupport/repo/",
            "this check and its tests, which name the references they refuse");

    private static final Set<String> INPUTS = Set.of("java", "xml", "sh", "properties", "bnd", "cfg", "conf",
            "mapping", "json", "yml", "yaml", "gradle");
    /** Text data counts as an input only under a module's {@code src/} (test resources, flats, scenarios). */
    private static final Set<String> INPUTS_UNDER_SRC = Set.of("txt", "csv");
    private static final Set<String> SKIPPED_DIRS = Set.of("target", "build", "node_modules", "felix-cache");

    private static final Pattern MACHINE = Pattern.compile("(?<![\\w.])/work/");
    /** The folder beside a clone where material is handed to the project: no build input may climb to it. */
    static final String HANDOVER_FOLDER = "shared";
    private static final Pattern UPS_SLASHED = Pattern.compile("(?<![\\w./-])((?:\\.\\./)+|\\.\\.(?=\"))");
    private static final Pattern UPS_LISTED = Pattern.compile("\"\\.\\.\"(?:\\s*,\\s*\"\\.\\.\")*");

    private OutsideReferences() {
    }

    /** @return one line per reference found: {@code path:line: what — the line} */
    static List<String> scan(Path root) {
        return scan(root, HANDOVER_FOLDER);
    }

    /** {@link #scan(Path)} with another name for the handover folder (the tests plant references to their own). */
    static List<String> scan(Path root, String handoverFolder) {
        Pattern sibling = Pattern.compile("\\.\\.(?:[\\s/\\\\\",]|\"\\)\\.resolve\\(\")*"
                + Pattern.quote(handoverFolder) + "\\b");
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(root)) {
            files.filter(Files::isRegularFile).filter(f -> scanned(root, f)).sorted()
                    .forEach(f -> scanFile(root, f, sibling, found));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot walk " + root, e);
        }
        return found;
    }

    static boolean scanned(Path root, Path file) {
        Path rel = root.relativize(file);
        String slashed = rel.toString().replace('\\', '/');
        if (ALLOWED.keySet().stream().anyMatch(slashed::startsWith)) {
            return false;
        }
        for (int i = 0; i < rel.getNameCount() - 1; i++) {
            String dir = rel.getName(i).toString();
            if (dir.startsWith(".") || SKIPPED_DIRS.contains(dir)) {
                return false;
            }
        }
        String name = file.getFileName().toString();
        String ext = name.substring(name.lastIndexOf('.') + 1);
        return INPUTS.contains(ext) || INPUTS_UNDER_SRC.contains(ext) && slashed.contains("src/");
    }

    private static void scanFile(Path root, Path file, Pattern sibling, List<String> found) {
        List<String> lines;
        try {
            lines = List.of(new String(Files.readAllBytes(file), StandardCharsets.UTF_8).split("\n", -1));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + file, e);
        }
        int depth = root.relativize(base(root, file)).toString().isEmpty() ? 0
                : root.relativize(base(root, file)).getNameCount();
        for (int i = 0; i < lines.size(); i++) {
            String why = check(lines.get(i), depth, sibling);
            if (why != null) {
                found.add(root.relativize(file) + ":" + (i + 1) + ": " + why + " — " + lines.get(i).strip());
            }
        }
    }

    /**
     * @return why the line reaches outside, or null; {@code depth}: folders between the root and the base,
     *         {@code sibling}: a climb to the handover folder
     */
    static String check(String line, int depth, Pattern sibling) {
        if (MACHINE.matcher(line).find()) {
            return "absolute path into this machine's /work";
        }
        if (sibling.matcher(line).find()) {
            return "climbs to a shared folder beside the clone";
        }
        int ups = Math.max(most(UPS_SLASHED.matcher(line), true), most(UPS_LISTED.matcher(line), false));
        return ups > depth ? ups + " steps up from a folder " + depth + " below the repository root" : null;
    }

    private static int most(Matcher m, boolean slashed) {
        int most = 0;
        while (m.find()) {
            String t = m.group();
            int ups = slashed ? Math.max(1, t.length() / 3) : (t.length() - t.replace("..", "").length()) / 2;
            most = Math.max(most, ups);
        }
        return most;
    }

    /** The folder a file's relative paths start from: a script's own, else the nearest one with a pom. */
    static Path base(Path root, Path file) {
        Path dir = file.getParent();
        if (file.getFileName().toString().endsWith(".sh")) {
            return dir;
        }
        for (Path d = dir; d.startsWith(root); d = d.getParent()) {
            if (Files.isRegularFile(d.resolve("pom.xml"))) {
                return d;
            }
        }
        return root;
    }
}
