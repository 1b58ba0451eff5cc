package org.tinysep.house.codec;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.repo.RepoFiles;

/** Every house file in the repository reads, and writing it back reads the same and is stable byte for byte. */
class CommittedHouseFilesTest {

    private static final Set<String> SKIPPED = Set.of("target", ".git", ".gradle", "build", "node_modules");

    /** @return every file named {@code house.xml} or {@code *house.xml} below the root, build output skipped */
    static List<Path> houseFiles() throws IOException {
        List<Path> found = new ArrayList<>();
        Files.walkFileTree(RepoFiles.root(), new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                return SKIPPED.contains(String.valueOf(dir.getFileName())) ? FileVisitResult.SKIP_SUBTREE
                        : FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                if (file.getFileName().toString().endsWith("house.xml") && attrs.isRegularFile()) {
                    found.add(file);
                }
                return FileVisitResult.CONTINUE;
            }
        });
        return found.stream().sorted().toList();
    }

    @Test
    void everyCommittedHouseFileRoundTrips() throws Exception {
        List<Path> files = houseFiles();
        List<String> names = files.stream().map(p -> RepoFiles.root().relativize(p).toString()).toList();
        for (String known : List.of("simulator/src/main/resources/flats/flat-a/house.xml",
                "simulator/src/main/resources/replay/ordonez-a.house.xml",
                "bundles/services/org.tinysep.houseinformation/src/test/resources/fig-3-7-house.xml")) {
            assertTrue(names.contains(known), known + " among " + names);
        }
        for (Path f : files) {
            HouseRooms read = HouseXml.read(Files.readAllBytes(f), f.toString());
            assertFalse(read.rooms().isEmpty(), f + " has rooms");
            byte[] written = HouseXml.toBytes(read);
            assertEquals(read, HouseXml.read(written, "written " + f), f + " reads back the same");
            assertArrayEquals(written, HouseXml.toBytes(HouseXml.read(written, "again")), f + " is stable");
        }
    }
}
