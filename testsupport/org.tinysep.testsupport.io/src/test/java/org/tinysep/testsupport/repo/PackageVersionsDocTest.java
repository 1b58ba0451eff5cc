package org.tinysep.testsupport.repo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * {@code docs/architecture.md}'s table "Package versions" names every versioned package of the repository with the
 * version and export its {@code package-info.java} declares, and nothing else: a version bump without the doc, or a
 * doc row for a package that went, fails the build naming the package.
 */
class PackageVersionsDocTest {

    private static final Pattern PACKAGE = Pattern.compile("(?m)^package\\s+([\\w.]+)\\s*;");
    private static final Pattern VERSION = Pattern.compile("@Version\\(\"([^\"]+)\"\\)");
    private static final Pattern EXPORT = Pattern.compile("(?m)^@Export\\b");
    private static final Pattern ROW = Pattern.compile("^\\| `([\\w.]+)` \\| (\\S+) \\| (yes|no) \\|");
    private static final String SECTION = "## Package versions";

    @Test
    void theArchitecturePageNamesEveryPackageVersionTheCodeDeclares() throws IOException {
        Path root = RepoFiles.root();
        Map<String, String> code = fromCode(root);
        Map<String, String> doc = fromDoc(root.resolve("docs/architecture.md"));
        assertEquals(List.of(), differences(code, doc),
                "docs/architecture.md, section \"" + SECTION + "\" needs one row `| `package` | version | yes/no |` per "
                        + "package-info.java carrying @Version (yes = @Export); these disagree");
    }

    static List<String> differences(Map<String, String> code, Map<String, String> doc) {
        Set<String> names = new TreeSet<>(code.keySet());
        names.addAll(doc.keySet());
        return names.stream().filter(n -> !Objects.equals(code.get(n), doc.get(n)))
                .map(n -> n + ": code " + Objects.requireNonNullElse(code.get(n), "(no package)") + ", doc "
                        + Objects.requireNonNullElse(doc.get(n), "(no row)"))
                .toList();
    }

    static Map<String, String> fromCode(Path root) throws IOException {
        Map<String, String> found = new TreeMap<>();
        try (Stream<Path> files = Files.walk(root)) {
            files.filter(p -> p.getFileName().toString().equals("package-info.java"))
                    .filter(p -> !isBuildOutput(root.relativize(p)))
                    .forEach(p -> {
                        String text = read(p);
                        Matcher version = VERSION.matcher(text);
                        Matcher name = PACKAGE.matcher(text);
                        if (version.find() && name.find()) {
                            found.put(name.group(1), version.group(1) + " "
                                    + (EXPORT.matcher(text).find() ? "yes" : "no"));
                        }
                    });
        }
        return found;
    }

    static Map<String, String> fromDoc(Path doc) throws IOException {
        Map<String, String> rows = new TreeMap<>();
        boolean inSection = false;
        for (String line : Files.readAllLines(doc)) {
            if (line.startsWith("## ")) {
                inSection = line.startsWith(SECTION);
            } else if (inSection) {
                Matcher row = ROW.matcher(line);
                if (row.find()) {
                    rows.put(row.group(1), row.group(2) + " " + row.group(3));
                }
            }
        }
        return rows;
    }

    private static boolean isBuildOutput(Path relative) {
        for (Path part : relative) {
            String name = part.toString();
            if (name.equals("target") || name.equals("build") || name.startsWith(".")) {
                return true;
            }
        }
        return false;
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
