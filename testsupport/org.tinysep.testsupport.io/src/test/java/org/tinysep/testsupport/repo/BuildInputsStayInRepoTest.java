package org.tinysep.testsupport.repo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The build's check of issue 32: no source, pom, bnd file, script, configuration or test resource of the repository
 * reads outside it, so a clone with nothing beside it tests green. This module builds before every module that
 * reads data, so a reference added anywhere fails the build here, naming the file and line.
 */
class BuildInputsStayInRepoTest {

    /** The planted references climb to a handover folder of this name; the real check climbs to its own. */
    private static final String HANDOUT = "handout";

    @TempDir
    Path tmp;

    @Test
    void noBuildOrTestInputOfTheRepositoryReachesOutsideIt() {
        List<String> found = OutsideReferences.scan(RepoFiles.root());
        assertTrue(found.isEmpty(), "build or test inputs that read outside the repository (a fresh clone has "
                + "nothing beside it: put test data under data/ with its PROVENANCE.md and read it through "
                + "org.tinysep.testsupport.repo.RepoFiles):\n" + String.join("\n", found) + "\n");
    }

    @Test
    void eachKindOfReferenceIsFoundWithItsFileAndLine() throws Exception {
        write("pom.xml", "<project><artifactId>tinysep-parent</artifactId></project>");
        write("simulator/pom.xml", "<relativePath>../pom.xml</relativePath>\n<directory>../../outside</directory>");
        write("simulator/src/test/java/X.java", String.join("\n",
                "Path a = Path.of(\"../../handout/data/ordonez\");",
                "Path b = Path.of(\"..\", \"..\", \"other\");",
                "Path c = Path.of(\"..\", \"itests\");",
                "Path d = Path.of(\"/work/handout/data\");",
                "Path e = repo.resolve(\"../handout/data\");",
                "Path f = Path.of(\"..\", \"handout\");"));
        write("simulator/src/test/resources/a.txt", "ok ../x\nfar ../../../x");
        write("scripts/x.sh", "cat ../simulator/pom.xml\ncat ../../elsewhere/file");
        write("evaluate.sh", "DATA=../handout/data/ordonez");
        write("README.md", "see ../handout/reference/tinysep-thesis.txt");
        write("simulator/target/classes/Y.java", "Path.of(\"../../handout\")");
        write("data/x/notes.txt", "copied from /work/handout/data/x");
        write("var/house.xml", "<file>/work/main/var/house.xml</file>");

        List<String> found = OutsideReferences.scan(tmp, HANDOUT).stream()
                .map(l -> l.substring(0, l.indexOf(" — "))).toList();

        assertEquals(List.of(
                "evaluate.sh:1: climbs to a shared folder beside the clone",
                "scripts/x.sh:2: 2 steps up from a folder 1 below the repository root",
                "simulator/pom.xml:2: 2 steps up from a folder 1 below the repository root",
                "simulator/src/test/java/X.java:1: climbs to a shared folder beside the clone",
                "simulator/src/test/java/X.java:2: 2 steps up from a folder 1 below the repository root",
                "simulator/src/test/java/X.java:4: absolute path into this machine's /work",
                "simulator/src/test/java/X.java:5: climbs to a shared folder beside the clone",
                "simulator/src/test/java/X.java:6: climbs to a shared folder beside the clone",
                "simulator/src/test/resources/a.txt:2: 3 steps up from a folder 1 below the repository root"), found);
    }

    private void write(String path, String text) throws Exception {
        Path p = tmp.resolve(path);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
    }
}
