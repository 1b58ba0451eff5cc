package org.tinysep.testsupport.repo;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Contracts between bundles are typed, in one place (issue 30, item 1): the web console's login mark, its public
 * pages and the board's acknowledge route are declared in {@code api/} ({@code org.tinysep.api.web}) only, and no
 * bundle loads another's classes by name ({@code DynamicImport-Package}) where a service belongs.
 */
class WebContractsInOnePlaceTest {

    /** A literal that declares a contract, and what it is. */
    private static final Map<String, String> DECLARATIONS = Map.of(
            "\"org.tinysep.web.role\"", "the login filter's request attribute (WebConsole.ROLE_ATTRIBUTE)",
            "\"/login.js\"", "the public page set (WebConsole.PUBLIC_PAGES)",
            "flats/[^/]+", "the board's acknowledge route (BoardRoutes)",
            "flats/([^/]+)", "the board's acknowledge route (BoardRoutes)");
    private static final Path HOME = Path.of("api", "src", "main", "java", "org", "tinysep", "api", "web");

    @Test
    void webContractsAreDeclaredOnlyInTheApi() {
        Path root = RepoFiles.root();
        List<String> found = new ArrayList<>();
        for (Path java : files(root, "java")) {
            Path rel = root.relativize(java);
            if (rel.startsWith(HOME) || rel.toString().contains("/src/test/") || rel.toString().contains("/target/")) {
                continue;
            }
            List<String> lines = read(java);
            for (int i = 0; i < lines.size(); i++) {
                String line = lines.get(i);
                for (Map.Entry<String, String> d : DECLARATIONS.entrySet()) {
                    if (line.contains(d.getKey())) {
                        found.add(rel + ":" + (i + 1) + ": declares " + d.getValue());
                    }
                }
            }
        }
        assertTrue(found.isEmpty(), "use org.tinysep.api.web instead of a copy:\n" + String.join("\n", found));
    }

    @Test
    void noBundleImportsClassesByNameDynamically() {
        Path root = RepoFiles.root();
        List<String> found = new ArrayList<>();
        for (Path bnd : files(root, "bnd")) {
            if (!bnd.toString().contains("/target/") && read(bnd).stream().anyMatch(l -> l.startsWith("DynamicImport-Package"))) {
                found.add(root.relativize(bnd).toString());
            }
        }
        assertTrue(found.isEmpty(), "DynamicImport-Package where a service belongs: " + found);
    }

    private static List<Path> files(Path root, String extension) {
        List<Path> all = new ArrayList<>();
        for (String top : List.of("libs", "bundles", "runtime")) {
            try (Stream<Path> s = Files.walk(root.resolve(top))) {
                s.filter(p -> p.getFileName().toString().endsWith("." + extension)).forEach(all::add);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return all;
    }

    private static List<String> read(Path p) {
        try {
            return Files.readAllLines(p);
        } catch (IOException e) {
            throw new UncheckedIOException(p.toString(), e);
        }
    }
}
