package org.tinysep.testsupport.repo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The one way tests reach data: inside the clone, never beside it. */
class RepoFilesTest {

    @TempDir
    Path tmp;

    @Test
    void findsTheRepositoryRootAboveTheModuleAndItsData() {
        Path root = RepoFiles.root();
        assertTrue(Files.isRegularFile(root.resolve("test.sh")), root.toString());
        assertEquals(root.resolve("data/ordonez/OrdonezA_Sensors.txt"),
                RepoFiles.require("data", "ordonez", "OrdonezA_Sensors.txt"));
    }

    @Test
    void refusesAPathBesideTheClone() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RepoFiles.resolve("..", "beside", "data", "ordonez"));
        assertTrue(e.getMessage().contains("outside the repository"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> RepoFiles.resolve("data/../../beside/data/ordonez"));
        assertThrows(IllegalArgumentException.class, () -> RepoFiles.require("simulator", "..", "..", "beside"));
    }

    @Test
    void refusesAnAbsolutePath() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RepoFiles.inside(RepoFiles.root(), tmp));
        assertTrue(e.getMessage().contains("is absolute"), e.getMessage());
    }

    @Test
    void refusesALinkThatLeadsOutOfTheRepository() throws Exception {
        Path repo = Files.createDirectories(tmp.resolve("clone/simulator"));
        Files.writeString(repo.resolveSibling("pom.xml"), "<project><artifactId>tinysep-parent</artifactId></project>");
        Files.writeString(repo.resolve("pom.xml"), "<project><parent><artifactId>tinysep-parent</artifactId>"
                + "</parent></project>");
        Path outside = Files.createDirectories(tmp.resolve("beside/data"));
        Files.writeString(outside.resolve("x.txt"), "beside the clone");
        Files.createSymbolicLink(repo.resolveSibling("data"), outside);

        Path root = RepoFiles.rootAbove(repo);
        assertEquals(tmp.resolve("clone").toRealPath(), root);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RepoFiles.inside(root, Path.of("data", "x.txt")));
        assertTrue(e.getMessage().contains("link"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> RepoFiles.inside(root, Path.of("data", "missing.txt")));
        assertEquals(root.resolve("simulator/pom.xml"), RepoFiles.inside(root, Path.of("simulator", "pom.xml")));
    }

    @Test
    void aMissingFileIsNamedWithWhereTheDataLives() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> RepoFiles.require("data", "ordonez", "OrdonezC_Sensors.txt"));
        assertTrue(e.getMessage().contains("OrdonezC_Sensors.txt is missing from the repository"), e.getMessage());
    }

    @Test
    void noRootAboveAFolderOutsideAnyClone() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> RepoFiles.rootAbove(tmp));
        assertTrue(e.getMessage().contains("no TinySEP repository above"), e.getMessage());
    }
}
