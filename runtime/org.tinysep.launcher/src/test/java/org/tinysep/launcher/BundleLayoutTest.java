package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class BundleLayoutTest {

    @TempDir
    Path bundles;

    @Test
    void groupsAreOrderedByNumericLevelAndJarsByName() throws IOException {
        jar("10-late/z.jar");
        jar("2-log/slf4j-simple-2.0.20.jar");
        jar("2-log/slf4j-api-2.0.20.jar");
        jar("1-boot/org.apache.aries.spifly.dynamic.bundle-1.3.7.jar");
        jar("1-boot/asm-9.8.jar");
        Files.createDirectories(bundles.resolve("5-apps"));

        List<BundleGroup> groups = BundleLayout.scan(bundles);

        assertEquals(List.of("1-boot", "2-log", "5-apps", "10-late"), groups.stream().map(BundleGroup::label).toList());
        assertEquals(List.of("asm-9.8.jar", "org.apache.aries.spifly.dynamic.bundle-1.3.7.jar"), names(groups.get(0)));
        assertEquals(List.of("slf4j-api-2.0.20.jar", "slf4j-simple-2.0.20.jar"), names(groups.get(1)));
        assertEquals(List.of(), names(groups.get(2)));
        assertEquals(10, BundleLayout.maxStartLevel(groups));
    }

    @Test
    void ignoresFilesOtherThanJarsAndFoldersWithoutLevel() throws IOException {
        jar("3-system/scr.jar");
        jar("3-system/README.txt");
        Files.createDirectories(bundles.resolve("3-system/nested"));
        jar("apps/x.jar");
        jar("0-zero/x.jar");
        jar("loose.jar");

        List<BundleGroup> groups = BundleLayout.scan(bundles);

        assertEquals(1, groups.size());
        assertEquals(3, groups.get(0).startLevel());
        assertEquals("system", groups.get(0).name());
        assertEquals(List.of("scr.jar"), names(groups.get(0)));
    }

    @Test
    void emptyLayoutStartsAtLevelOne() throws IOException {
        assertEquals(1, BundleLayout.maxStartLevel(BundleLayout.scan(bundles)));
    }

    @Test
    void missingFolderIsAnError() {
        assertThrows(IOException.class, () -> BundleLayout.scan(bundles.resolve("nope")));
    }

    private void jar(String relative) throws IOException {
        Path file = bundles.resolve(relative);
        Files.createDirectories(file.getParent());
        Files.write(file, new byte[0]);
    }

    private static List<String> names(BundleGroup group) {
        return group.jars().stream().map(p -> p.getFileName().toString()).toList();
    }
}
