package org.tinysep.testsupport.repo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The README's "Layout" table is the map of the tree: every folder it names exists, and every module of the Maven
 * build (read from the poms' {@code <modules>}, as the Gradle build reads them) is either a row itself or lies
 * directly in a folder that is a row, so a module's layer can be told from its path. A module added in a folder the
 * table does not name, or a row left behind by a move, fails the build naming it.
 */
class LayoutTableTest {

    private static final Pattern MODULE = Pattern.compile("<module>([^<]+)</module>");
    private static final Pattern FOLDER = Pattern.compile("`([\\w./-]+/)`");

    @Test
    void theReadmeLayoutTableNamesTheFolderOfEveryModuleAndOnlyFoldersThatExist() throws IOException {
        Path root = RepoFiles.root();
        Set<String> rows = rows(Files.readAllLines(root.resolve("README.md")));
        assertEquals(List.of(), problems(root, rows, modules(root, "")),
                "README.md \"## Layout\": rows (first column, `folder/`) and the build's modules disagree");
    }

    @Test
    void aModuleInAFolderTheTableDoesNotNameIsReported() {
        Path root = RepoFiles.root();
        assertEquals(List.of("module elsewhere/org.tinysep.x/ lies in no folder of the table",
                "row gone/ is not a folder"),
                problems(root, Set.of("api/", "gone/"), List.of("api", "elsewhere/org.tinysep.x")));
    }

    static List<String> problems(Path root, Set<String> rows, List<String> modules) {
        List<String> problems = new ArrayList<>();
        for (String m : modules) {
            String parent = m.contains("/") ? m.substring(0, m.lastIndexOf('/') + 1) : "";
            if (!rows.contains(m + "/") && !rows.contains(parent)) {
                problems.add("module " + m + "/ lies in no folder of the table");
            }
        }
        for (String row : rows) {
            if (!Files.isDirectory(root.resolve(row))) {
                problems.add("row " + row + " is not a folder");
            }
        }
        return problems;
    }

    /** @return the folders named in the first column of the table under "## Layout" */
    static Set<String> rows(List<String> readme) {
        Set<String> rows = new LinkedHashSet<>();
        boolean in = false;
        for (String line : readme) {
            if (line.startsWith("## ")) {
                in = line.equals("## Layout");
            } else if (in && line.startsWith("| ")) {
                Matcher m = FOLDER.matcher(line.substring(2, line.indexOf(" |", 1)));
                while (m.find()) {
                    rows.add(m.group(1));
                }
            }
        }
        return rows;
    }

    /** @return the build's modules that are not aggregators, as paths from the root, e.g. {@code bundles/...} */
    static List<String> modules(Path root, String dir) throws IOException {
        String pom = Files.readString(root.resolve(dir).resolve("pom.xml"));
        List<String> found = new ArrayList<>();
        if (!pom.contains("<packaging>pom</packaging>")) {
            found.add(dir);
            return found;
        }
        Matcher m = MODULE.matcher(pom);
        while (m.find()) {
            found.addAll(modules(root, dir.isEmpty() ? m.group(1).trim() : dir + "/" + m.group(1).trim()));
        }
        return found;
    }
}
